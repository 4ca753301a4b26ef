// Running the real coremodal program from a test: a scratch folder, the
// program's exit code, stdout and stderr. Shared by the command-line tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

// Runs `prefix coremodal args` inside dir, so that case files are named
// relatively ("bad.toml:4:18: ..."). The test binary itself is an MPI
// singleton; the Open MPI and PMIx variables that puts in our environment
// must not reach the child, or its MPI_Init (and mpirun) would try to join
// this process's job.
inline Run run_coremodal(const TempDir& dir, const std::string& args, const std::string& prefix = "") {
    const std::string command = "cd '" + dir.path.string() +
                                "' && unset $(env | grep -E '^(OMPI_|PMIX_|OPAL_|ORTE_)' | grep -v "
                                "'^OMPI_ALLOW_RUN_AS_ROOT' | cut -d= -f1) && " +
                                prefix + "'" COREMODAL_BINARY "' " + args + " >stdout.txt 2>stderr.txt";
    const int status = std::system(command.c_str());
    Run r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(dir.path / "stdout.txt");
    r.err = slurp(dir.path / "stderr.txt");
    std::filesystem::remove(dir.path / "stdout.txt");
    std::filesystem::remove(dir.path / "stderr.txt");
    return r;
}

}  // namespace coremodal::testing
