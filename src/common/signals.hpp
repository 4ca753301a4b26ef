// Interrupts: what coremodal does on SIGINT (Ctrl-C), SIGTERM (kill, a
// batch system's time limit), SIGHUP (the terminal closed), SIGQUIT (the
// quit key) and SIGPIPE (the reader of stdout gone: `coremodal run ... |
// head`). It stops the child processes it started (python plots, study
// workers, batch cases), waits for them, removes the folders it was still
// writing (a results folder's "<dir>.partial-<pid>", a study's scratch
// folder) and exits 128 + signal, the shell's convention (130 for SIGINT,
// 143 for SIGTERM, 129, 131, 141), saying so on stderr, except after
// SIGPIPE, which ends a program in a pipe quietly. A folder already
// complete is kept.
//
// The signal handler does one async-signal-safe thing: it writes the
// signal's number into a pipe (the self-pipe trick). A thread waiting on the
// pipe does the rest as ordinary code that may lock, allocate and remove
// folders. (Blocking the signals and taking them with sigwait would need every
// thread to block them, and libraries start threads before main: OpenBLAS
// its pool, which would then take SIGTERM with its default action.) SIGKILL
// cannot be caught: the stale sweep of output/results_folder.hpp removes
// what a killed process left.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <stdexcept>

namespace coremodal {

// What code that asks for the interrupted state throws: the interrupt is
// being handled, the process is about to exit with its own status.
class Interrupted : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Installs the handler of those signals (and, the first time, starts
// the thread that waits for them). Call it first thing in main() and again
// after PetscInitialize, which installs PETSc's own SIGTERM handler. A signal
// that was ignored when the program started (a background job of a
// non-interactive shell ignores SIGINT) stays ignored.
void install_interrupt_handling();

// The signal being handled, 0 while none has arrived.
int interrupt_signal();

// Runs `action` unless an interrupt has arrived, and keeps the interrupt's
// clean-up from starting until it has returned: what is done under it is
// done completely or not at all (a results folder's rename into place).
// Throws Interrupted when an interrupt has arrived.
void unless_interrupted(const std::function<void()>& action);

// Folders removed on an interrupt; each is registered for the time it is
// incomplete. Registering throws Interrupted when an interrupt has arrived.
void remove_on_interrupt(const std::filesystem::path& folder);
void keep_on_interrupt(const std::filesystem::path& folder);

// Child processes stopped on an interrupt (common/child_process.cpp
// registers every child it starts, from its start until it has been reaped).
// Registering after an interrupt sends the child the signal at once.
void child_started(pid_t pid);
void child_reaped(pid_t pid);

// For main(): after an interrupt, waits for the interrupt thread to end the
// process (so that an error caused by the clean-up, e.g. a file that can no
// longer be written, never becomes the exit status); returns at once otherwise.
void wait_if_interrupted();

}  // namespace coremodal
