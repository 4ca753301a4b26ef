#include "output/python_plots.hpp"

#include "common/child_process.hpp"
#include "common/signals.hpp"

#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>

extern char** environ;

namespace coremodal {
namespace fs = std::filesystem;
namespace {

// The last line of the log that is not blank: python's one-line error
// ("ModuleNotFoundError: No module named 'matplotlib'", "coremodal: error: ...").
std::string last_line(const fs::path& file) {
    std::ifstream in(file);
    std::string line, last;
    while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    return last;
}

// The folder holding the python package: $COREMODAL_PYTHON_DIR if set; an
// installed program's own (COREMODAL_PYTHON_FROM_BIN from the folder of the
// executable, e.g. PREFIX/bin/../share/coremodal/python) when it is there;
// else this source tree's python/.
std::string package_folder() {
    const char* own = std::getenv("COREMODAL_PYTHON_DIR");
    if (own && *own) return own;
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        const fs::path installed = exe.parent_path() / COREMODAL_PYTHON_FROM_BIN;
        if (fs::is_regular_file(installed / "coremodal" / "__init__.py", error))
            return installed.lexically_normal().string();
    }
    return COREMODAL_SOURCE_DIR "/python";
}

// Our environment with PYTHONPATH led by the package folder and the Agg
// backend (no display: the pictures are files).
std::vector<std::string> plot_environment() {
    std::string pythonpath = package_folder();
    std::vector<std::string> env;
    for (char** e = environ; e && *e; ++e) {
        const std::string v = *e;
        if (v.rfind("PYTHONPATH=", 0) == 0) {
            if (v.size() > 11) pythonpath.append(":").append(v, 11);
        } else if (v.rfind("MPLBACKEND=", 0) != 0) {
            env.push_back(v);
        }
    }
    env.push_back("PYTHONPATH=" + pythonpath);
    env.push_back("MPLBACKEND=Agg");
    return env;
}

}  // namespace

std::string python_interpreter() {
    const char* own = std::getenv("COREMODAL_PYTHON");
    return own && *own ? own : COREMODAL_PYTHON;
}

std::string run_python_plot(const std::string& subcommand, const fs::path& folder,
                            const std::vector<std::string>& args) {
    const std::string python = python_interpreter();
    const std::string what = python + " -m coremodal " + subcommand;
    const fs::path log = folder / "plot.log";
    std::vector<std::string> argv_strings = {python, "-m", "coremodal", subcommand, folder.string()};
    argv_strings.insert(argv_strings.end(), args.begin(), args.end());
    const ChildExit child = run_child(python, argv_strings, plot_environment(), log, /*search_path=*/true);
    // Stopped by an interrupt (common/signals.hpp): no warning about pictures
    // of a run that is being abandoned.
    if (interrupt_signal()) throw Interrupted("interrupted while drawing");
    if (!child.started()) {
        std::error_code ignored;
        fs::remove(log, ignored);
        return what + " could not start: " + std::strerror(child.spawn_error);
    }
    const int status = child.status;
    if (child.succeeded()) {
        std::error_code ignored;
        fs::remove(log, ignored);
        return "";
    }
    const std::string why = last_line(log);
    const std::string how = WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                              : "signal " + std::to_string(WTERMSIG(status));
    return what + " failed (" + how + ")" + (why.empty() ? std::string() : ": " + why) + " (log: plot.log)";
}

Pictures draw_pictures(const std::string& subcommand, const fs::path& folder, bool no_plots,
                       const std::vector<std::string>& pngs) {
    Pictures out;
    out.problem = no_plots ? "switched off (--no-plots)" : run_python_plot(subcommand, folder);
    if (out.problem.empty()) out.pngs = pngs;
    else if (!no_plots)
        std::cerr << "coremodal: warning: plots not drawn: " << out.problem << "; the tables and report.md are "
                  << "complete (draw them later with python3 -m coremodal " << subcommand << " DIR)" << std::endl;
    return out;
}

}  // namespace coremodal
