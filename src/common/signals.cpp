#include "common/signals.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace coremodal {
namespace fs = std::filesystem;

namespace {

// How long children get after the signal is passed on before SIGKILL: a
// coremodal child removes its own partial folder and stops its own children
// (well under a second); python unwinds its KeyboardInterrupt.
constexpr auto kChildGrace = std::chrono::seconds(10);
// After SIGKILL, how long to wait for the threads that started the children
// to reap them (the kernel ends a killed process at once).
constexpr auto kKilledGrace = std::chrono::seconds(2);
// A folder may still be written by another thread (this process's main
// thread does not stop for the interrupt): removing it is retried until it
// stays gone, this many times, kPoll apart.
constexpr int kRemoveAttempts = 50;
constexpr auto kPoll = std::chrono::milliseconds(20);

struct State {
    std::mutex lock;
    std::atomic<int> signal{0};
    std::set<pid_t> children;
    std::set<fs::path> folders;
    // Children registered after the signal (forked just before it, recorded
    // just after): child_started stops them itself.
    size_t stopped_late = 0;
};

// Never destroyed: the interrupt thread may use it while the main thread
// runs the static destructors of a normal exit.
State& state() {
    static State* s = new State;
    return *s;
}

std::set<pid_t> running_children() {
    std::lock_guard<std::mutex> guard(state().lock);
    return state().children;
}

// Passes `sig` on to every child, waits for them to be reaped, and kills
// those that outlive kChildGrace. Returns how many there were, those
// child_started stopped meanwhile included.
size_t stop_children(int sig) {
    const std::set<pid_t> first = running_children();
    for (pid_t pid : first) ::kill(pid, sig);
    for (auto [resend, grace] : {std::pair{0, kChildGrace}, std::pair{SIGKILL, kKilledGrace}}) {
        if (resend)
            for (pid_t pid : running_children()) ::kill(pid, resend);
        const auto until = std::chrono::steady_clock::now() + grace;
        while (!running_children().empty() && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(kPoll);
        if (running_children().empty()) break;
    }
    std::lock_guard<std::mutex> guard(state().lock);
    return first.size() + state().stopped_late;
}

// Removes the folders, which another thread may still be writing into.
void remove_folders(const std::vector<fs::path>& folders) {
    for (const fs::path& folder : folders)
        for (int attempt = 0; attempt < kRemoveAttempts; ++attempt) {
            std::error_code ec;
            fs::remove_all(folder, ec);
            if (!fs::exists(fs::symlink_status(folder, ec))) break;
            std::this_thread::sleep_for(kPoll);
        }
}

// The interrupt thread's work once a signal has arrived. Setting the signal
// under the lock waits for a rename in progress (unless_interrupted) and
// stops any later one, and no folder is registered after it: the folders
// registered now are all there are (the main thread may still remove one
// itself as it unwinds). Children go first, because a python plot writes
// into the partial folder that is removed next.
// The signal's name, for the line that says why the run ended.
const char* signal_name(int sig) {
    switch (sig) {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        case SIGHUP: return "SIGHUP";
        case SIGQUIT: return "SIGQUIT";
        case SIGPIPE: return "SIGPIPE";
        default: return "a signal";
    }
}

[[noreturn]] void handle_interrupt(int sig) {
    std::vector<fs::path> removed;
    {
        std::lock_guard<std::mutex> guard(state().lock);
        state().signal = sig;
        removed.assign(state().folders.begin(), state().folders.end());
    }
    // The children's stdout is not the closed pipe (python ignores SIGPIPE):
    // they are stopped with SIGTERM.
    const size_t n_children = stop_children(sig == SIGPIPE ? SIGTERM : sig);
    remove_folders(removed);
    std::string line = std::string("coremodal: interrupted by ") + signal_name(sig);
    if (n_children) line += "; stopped " + std::to_string(n_children) + " child process(es)";
    for (const fs::path& f : removed) line += "; removed " + f.string();
    // A reader that stopped reading (`coremodal run ... | head`) ends the run
    // quietly, as it ends any program in a pipe: the clean-up, no message.
    if (sig != SIGPIPE) std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stdout);
    std::fflush(stderr);
    ::_exit(128 + sig);
}

// The signals that end a run as Ctrl-C does: a terminal closed (HUP), the
// quit key (QUIT, which would otherwise dump core), a reader gone from the pipe on
// stdout (PIPE; a write to it then fails with EPIPE and the run ends here).
// PETSc installs its own handler for all of them ("Caught signal", exit 59).
constexpr int kInterrupts[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};

// The pipe from the signal handler to the interrupt thread.
int signal_pipe[2] = {-1, -1};

// Signal context: only async-signal-safe calls. write(2) is one; errno is
// kept for the code the signal interrupted.
extern "C" void on_signal(int sig) {
    const int saved = errno;
    const unsigned char byte = static_cast<unsigned char>(sig);
    [[maybe_unused]] const ssize_t written = ::write(signal_pipe[1], &byte, 1);
    errno = saved;
}

}  // namespace

void install_interrupt_handling() {
    static const bool started = [] {
        if (::pipe2(signal_pipe, O_CLOEXEC) != 0) return false;
        ::fcntl(signal_pipe[1], F_SETFL, O_NONBLOCK);  // a flood of signals never blocks the handler
        std::thread([] {
            unsigned char sig = 0;
            while (::read(signal_pipe[0], &sig, 1) != 1) {
            }
            handle_interrupt(sig);
        }).detach();
        return true;
    }();
    if (!started) return;  // no pipe: the signals keep their default action
    // Which were ignored when the program started, before PETSc put its
    // handlers on them: those stay ignored.
    static const std::set<int> ignored = [] {
        std::set<int> out;
        for (int sig : kInterrupts) {
            struct sigaction now {};
            if (::sigaction(sig, nullptr, &now) != 0 || now.sa_handler == SIG_IGN) out.insert(sig);
        }
        return out;
    }();
    for (int sig : kInterrupts) {
        if (ignored.count(sig)) continue;
        struct sigaction ours {};
        ours.sa_handler = on_signal;
        sigemptyset(&ours.sa_mask);
        ours.sa_flags = SA_RESTART;
        ::sigaction(sig, &ours, nullptr);
    }
    // A file-size limit (ulimit -f, a job's quota of that kind) reached while
    // writing: by default SIGXFSZ kills the run, leaving its partial folder and
    // lock file. Ignored, the write fails with EFBIG instead, and the writer
    // reports it as it does a full disk (failure injection, issue 33).
    ::signal(SIGXFSZ, SIG_IGN);
}

int interrupt_signal() { return state().signal; }

void unless_interrupted(const std::function<void()>& action) {
    std::lock_guard<std::mutex> guard(state().lock);
    if (state().signal) throw Interrupted("interrupted");
    action();
}

void remove_on_interrupt(const fs::path& folder) {
    std::lock_guard<std::mutex> guard(state().lock);
    if (state().signal) throw Interrupted("interrupted");
    state().folders.insert(folder);
}

void keep_on_interrupt(const fs::path& folder) {
    std::lock_guard<std::mutex> guard(state().lock);
    state().folders.erase(folder);
}

void child_started(pid_t pid) {
    std::lock_guard<std::mutex> guard(state().lock);
    state().children.insert(pid);
    if (!state().signal) return;
    const int sig = state().signal;
    ::kill(pid, sig == SIGPIPE ? SIGTERM : sig);
    ++state().stopped_late;
}

void child_reaped(pid_t pid) {
    std::lock_guard<std::mutex> guard(state().lock);
    state().children.erase(pid);
}

void wait_if_interrupted() {
    if (!state().signal) return;
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
}

}  // namespace coremodal
