#include "common/child_process.hpp"

#include "common/argv.hpp"
#include "common/signals.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <set>
#include <sstream>

extern char** environ;

namespace coremodal {
namespace {

bool belongs_to_our_mpi_job(const std::string& name) {
    if (name.rfind("OMPI_ALLOW_RUN_AS_ROOT", 0) == 0) return false;
    for (const char* prefix : {"OMPI_", "PMIX_", "OPAL_", "ORTE_"})
        if (name.rfind(prefix, 0) == 0) return true;
    return false;
}

}  // namespace

std::vector<std::string> child_environment(bool single_threaded) {
    std::vector<std::string> env;
    std::set<std::string> names;
    for (char** e = environ; e && *e; ++e) {
        const std::string entry = *e;
        const std::string name = entry.substr(0, entry.find('='));
        if (belongs_to_our_mpi_job(name)) continue;
        env.push_back(entry);
        names.insert(name);
    }
    if (single_threaded)
        for (const char* name : {"OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS"})
            if (!names.count(name)) env.push_back(std::string(name) + "=1");
    return env;
}

bool ChildExit::succeeded() const { return started() && WIFEXITED(status) && WEXITSTATUS(status) == 0; }

ChildExit run_child(const std::string& program, std::vector<std::string> args, std::vector<std::string> env,
                    const std::filesystem::path& log, bool search_path) {
    ChildExit out;
    if (interrupt_signal()) {  // the process is stopping: start nothing new
        out.spawn_error = ECANCELED;
        return out;
    }
    auto argv = c_strings(args);
    auto envp = c_strings(env);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    out.spawn_error = search_path
                          ? posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data())
                          : posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (out.spawn_error != 0) return out;
    child_started(pid);  // an interrupt stops it (and waits until it has been reaped here)
    while (waitpid(pid, &out.status, 0) < 0 && errno == EINTR) {
    }
    child_reaped(pid);
    out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

std::string first_error_line(const std::string& log_text) {
    std::vector<std::string> lines;
    std::istringstream in(log_text);
    for (std::string line; std::getline(in, line);) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
        if (!line.empty()) lines.push_back(line);
    }
    const std::string prefix = "coremodal: ";
    for (const auto& l : lines)
        if (l.rfind(prefix, 0) == 0) return l.substr(prefix.size());
    for (const auto& l : lines) {
        std::string lower = l;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return std::tolower(ch); });
        if (lower.find("error") != std::string::npos) return l;
    }
    return lines.empty() ? "" : lines.back();
}

}  // namespace coremodal
