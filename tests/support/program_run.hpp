// Running the real coremodal program from a test: a scratch folder, the
// program's exit code, stdout and stderr. Shared by the command-line tests.
#pragma once

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

extern char** environ;

namespace coremodal::testing {

// A fresh folder under the system temp folder, removed with the object.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& tag = "cli") {
        static int counter = 0;
        path = std::filesystem::temp_directory_path() /
               ("coremodal_test_" + tag + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    void write(const std::string& name, const std::string& text) const { std::ofstream(path / name) << text; }
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Run {
    int exit_code = -1;
    std::string out, err;
};

// The shell command that runs `prefix coremodal args` inside dir, so that
// case files are named relatively ("bad.toml:4:18: ..."), output into
// dir/stdout.txt and dir/stderr.txt. The test binary itself is an MPI
// singleton; the Open MPI and PMIx variables that puts in our environment
// must not reach the child, or its MPI_Init (and mpirun) would try to join
// this process's job. `prefix` is a command and/or NAME=value settings
// (`exec env` takes both, and keeps the shell's process number).
inline std::string coremodal_command(const TempDir& dir, const std::string& args, const std::string& prefix) {
    return "cd '" + dir.path.string() +
           "' && unset $(env | grep -E '^(OMPI_|PMIX_|OPAL_|ORTE_)' | grep -v "
           "'^OMPI_ALLOW_RUN_AS_ROOT' | cut -d= -f1) && exec env " +
           prefix + " '" COREMODAL_BINARY "' " + args + " >stdout.txt 2>stderr.txt";
}

inline Run collect_output(const TempDir& dir, int status) {
    Run r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(dir.path / "stdout.txt");
    r.err = slurp(dir.path / "stderr.txt");
    std::filesystem::remove(dir.path / "stdout.txt");
    std::filesystem::remove(dir.path / "stderr.txt");
    return r;
}

// Runs coremodal to the end (coremodal_command).
inline Run run_coremodal(const TempDir& dir, const std::string& args, const std::string& prefix = "") {
    return collect_output(dir, std::system(coremodal_command(dir, args, prefix).c_str()));
}

// A coremodal started in the background (start_coremodal), in a process
// group of its own: if the test ends before finish_coremodal collected it,
// the group (coremodal and every child) is killed.
struct Started {
    pid_t pid = -1;
    explicit Started(pid_t p) : pid(p) {}
    Started(const Started&) = delete;
    Started& operator=(const Started&) = delete;
    ~Started() {
        if (pid <= 0) return;
        kill(-pid, SIGKILL);
        waitpid(pid, nullptr, 0);
    }
};

// Starts coremodal in the background (coremodal_command); `pid` is
// coremodal's own process number, for sending it signals.
inline Started start_coremodal(const TempDir& dir, const std::string& args, const std::string& prefix = "") {
    std::string shell = "/bin/sh", flag = "-c", command = coremodal_command(dir, args, prefix);
    char* argv[] = {shell.data(), flag.data(), command.data(), nullptr};
    // The interrupts as a program started from a terminal has them (a test
    // binary started in the background may have inherited SIGINT ignored).
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t interrupts;
    sigemptyset(&interrupts);
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) sigaddset(&interrupts, sig);
    posix_spawnattr_setsigdefault(&attributes, &interrupts);
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);
    pid_t pid = -1;
    const int failed = posix_spawn(&pid, "/bin/sh", nullptr, &attributes, argv, environ);
    posix_spawnattr_destroy(&attributes);
    return Started(failed ? -1 : pid);
}

// Waits up to timeout_s for a started coremodal to end and collects its
// output; nothing (and the process killed) if it does not end in time.
inline std::optional<Run> finish_coremodal(const TempDir& dir, Started& started, double timeout_s) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    int status = 0;
    while (waitpid(started.pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > until) return std::nullopt;  // ~Started kills it
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    started.pid = -1;
    return collect_output(dir, status);
}

// Whether `done()` came true within timeout_s (polled every 20 ms).
template <class Condition>
bool wait_until(Condition done, double timeout_s) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (!done()) {
        if (std::chrono::steady_clock::now() > until) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

}  // namespace coremodal::testing
