// Scratch folders named by the process that made them ("<prefix><pid>": a
// study's /tmp/coremodal-study-<pid>, an MPI rank's shared-memory folder
// /dev/shm/coremodal-mpi-<pid>), and their removal once that process is gone.
// A process removes its own when it ends or is interrupted; SIGKILL cannot be
// caught, so a killed one cannot, and the next coremodal removes what it left.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string_view>

namespace coremodal {

// Whether `pid` is a running coremodal (a process number the system has
// given to another program since does not count, nor a killed process not
// yet reaped).
bool coremodal_running(pid_t pid);

// "<parent>/<prefix><pid>".
std::filesystem::path process_folder(const std::filesystem::path& parent, std::string_view prefix, pid_t pid);

// Removes the folders "<parent>/<prefix><pid>" of this user (not symbolic
// links, not another user's) whose process is gone or is no coremodal, and
// never this process's own; returns how many were removed.
int remove_folders_of_dead_processes(const std::filesystem::path& parent, std::string_view prefix);

}  // namespace coremodal
