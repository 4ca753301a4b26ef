// What an MPI job killed whole with SIGKILL leaves in /dev/shm, and its
// removal by the next coremodal (issue 33, item 10; common/mpi_start.hpp).
#include "common/mpi_start.hpp"
#include "common/process_folders.hpp"
#include "support/program_run.hpp"
#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <set>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

const fs::path kShm = coremodal::MpiSharedMemoryFolder::kParent;

// The parent process of `pid`, 0 when it is gone.
pid_t parent_of(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line) || line.rfind(')') == std::string::npos) return 0;
    std::istringstream rest(line.substr(line.rfind(')') + 2));
    char state = 0;
    pid_t parent = 0;
    rest >> state >> parent;
    return parent;
}

// The shared-memory folders of the ranks `launcher` started that hold
// Open MPI's segment file.
std::set<fs::path> rank_folders_with_segments(pid_t launcher) {
    std::set<fs::path> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(kShm, ec)) {
        const std::string name = entry.path().filename().string();
        const std::string prefix = coremodal::MpiSharedMemoryFolder::kPrefix;
        if (name.rfind(prefix, 0) != 0) continue;
        const pid_t rank = static_cast<pid_t>(std::atol(name.c_str() + prefix.size()));
        if (parent_of(rank) != launcher) continue;
        for (const auto& file : fs::directory_iterator(entry.path(), ec))
            if (file.path().filename().string().rfind("vader_segment.", 0) == 0) found.insert(entry.path());
    }
    return found;
}

}  // namespace

TEST_CASE("Shared memory of an MPI job killed with SIGKILL is removed by the next run", "[app][signals][shm]") {
    if (!fs::is_directory(kShm)) {
        WARN("skipped: no /dev/shm on this machine");
        return;
    }
    TempDir dir("shm");
    // A solve of some seconds (2 x 16 x 40 hex20), to be killed in.
    std::string slow = kTinyCase;
    slow.replace(slow.find("around = 8"), 10, "around = 16");
    slow.replace(slow.find("along = 4"), 9, "along = 40");
    dir.write("slow.toml", slow);
    dir.write("tiny.toml", kTinyCase);

    Started job = start_coremodal(dir, "run slow.toml -o out -q --no-plots",
                                  "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 2 --oversubscribe");
    std::set<fs::path> folders;
    // Each rank's segment in a folder of its own (before: /dev/shm/vader_segment.<host>.<uid>.<job>.<rank>).
    REQUIRE(wait_until([&] { return (folders = rank_folders_with_segments(job.pid)).size() == 2; }, 90));
    ::kill(-job.pid, SIGKILL);  // mpirun and both ranks: nobody left to clean up
    REQUIRE(finish_coremodal(dir, job, 20));
    const auto ranks_gone = [&] {
        for (const fs::path& f : folders)
            if (coremodal::coremodal_running(std::atoi(f.filename().c_str() + std::strlen(coremodal::MpiSharedMemoryFolder::kPrefix))))
                return false;
        return true;
    };
    REQUIRE(wait_until(ranks_gone, 20));
    // What SIGKILL leaves. Any coremodal that starts removes such folders
    // (common/process_folders.hpp), and ctest runs other tests beside this
    // one: if one of them started in between, the removal cannot be
    // credited to the next run, so the test stops here (it failed once so in
    // a full suite, 2026-11-29, and passed alone and under load).
    if (!std::all_of(folders.begin(), folders.end(), [](const fs::path& f) { return fs::exists(f); })) {
        WARN("the killed job's folders were removed before the next run (another coremodal started meanwhile)");
        return;
    }

    const Run next = run_coremodal(dir, "run tiny.toml --model beam -o next -q --no-plots");
    INFO("stderr: " << next.err);
    CHECK(next.exit_code == 0);
    for (const fs::path& f : folders) {
        INFO(f);
        CHECK_FALSE(fs::exists(f));
    }
}

TEST_CASE("A run under mpirun removes its shared-memory folders when it ends", "[app][shm]") {
    if (!fs::is_directory(kShm)) {
        WARN("skipped: no /dev/shm on this machine");
        return;
    }
    TempDir dir("shm");
    dir.write("tiny.toml", kTinyCase);
    Started job = start_coremodal(dir, "run tiny.toml -o out -q --no-plots",
                                  "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 2 --oversubscribe");
    // The folders seen while it runs (the ranks' numbers are gone after).
    std::set<fs::path> folders;
    std::optional<Run> r;
    for (int polls = 0; !r && polls < 2400; ++polls) {  // 2 minutes
        for (const fs::path& f : rank_folders_with_segments(job.pid)) folders.insert(f);
        r = finish_coremodal(dir, job, 0.05);
    }
    REQUIRE(r);
    INFO("stderr: " << r->err);
    CHECK(r->exit_code == 0);
    REQUIRE(folders.size() == 2);
    for (const fs::path& f : folders) {
        INFO(f);
        CHECK_FALSE(fs::exists(f));
    }
}
