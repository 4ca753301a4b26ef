// Running another program as a child: the batch's cases, a study's points
// and the python plots all start one the same way and wait for it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

struct ChildExit {
    int spawn_error = 0;  // errno of a child that never started (then status is meaningless)
    int status = 0;       // waitpid's status: WIFEXITED / WEXITSTATUS / WIFSIGNALED
    double wall_s = 0;    // from the start to the end of the child's life
    bool started() const { return spawn_error == 0; }
    bool succeeded() const;  // started, exited, status 0
};

// This process's environment for a child coremodal or python: without the
// variables this process's MPI singleton put there (a child that inherits
// them tries to join our MPI job instead of starting its own) and, with
// single_threaded, one BLAS/OpenMP thread (unless the user set it), so that
// J children at a time do not each start one thread per core.
std::vector<std::string> child_environment(bool single_threaded);

// Runs `program` with `args` (args[0] is the child's argv[0]) in the
// environment `env` ("NAME=value" entries), standard input from /dev/null and
// standard output and error into `log`; returns when it has ended. With
// search_path the program is looked up on PATH as a shell would. Every child
// is registered with common/signals.hpp while it runs, so that SIGINT or
// SIGTERM to this process reaches it too; after an interrupt no child starts
// (spawn_error ECANCELED).
ChildExit run_child(const std::string& program, std::vector<std::string> args, std::vector<std::string> env,
                    const std::filesystem::path& log, bool search_path = false);

// The line of a child's log that explains its failure: the first
// "coremodal: ..." line (prefix removed), else the first line mentioning an
// error, else the last non-empty line; "" for an empty log.
std::string first_error_line(const std::string& log_text);

}  // namespace coremodal
