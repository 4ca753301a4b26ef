// The results-folder rule (output/results_folder.hpp): coremodal replaces
// only folders it wrote, keeps the replaced one as .previous, refuses the
// user's files and folders, the working and home folders and their parents,
// and sweeps the partial folders of processes that no longer run.
#include "output/results_folder.hpp"
#include "output/text_file.hpp"

#include "common/error.hpp"
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal;
using coremodal::testing::slurp;
using coremodal::testing::TempDir;

extern char** environ;

namespace {

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string this_host() {
    char name[256] = {};
    ::gethostname(name, sizeof name - 1);
    return name;
}

// A folder that looks like coremodal's: the marker (naming `host`) and a file.
void fake_result(const fs::path& folder, const std::string& content, const std::string& host = this_host()) {
    fs::create_directories(folder);
    write(folder / kResultsMarker, "coremodal results folder\nversion 0\ncommand test\nhost " + host + "\n");
    write(folder / "summary.json", content);
}

// The number of a process that has ended (spawned and reaped here).
int dead_pid() {
    pid_t pid = 0;
    char arg0[] = "true";
    char* argv[] = {arg0, nullptr};
    REQUIRE(posix_spawn(&pid, "/bin/true", nullptr, nullptr, argv, environ) == 0);
    int status = 0;
    waitpid(pid, &status, 0);
    return pid;
}

// The message prepare_output refuses `path` with ("" when it accepts it).
std::string refusal(const fs::path& path, bool force = false) {
    try {
        prepare_output(path, force);
        return "";
    } catch (const InputError& e) {
        return e.what();
    }
}

// Sets an environment variable for the lifetime of the object.
struct ScopedEnv {
    std::string name;
    std::optional<std::string> old;
    ScopedEnv(std::string n, const std::string& value) : name(std::move(n)) {
        if (const char* v = std::getenv(name.c_str())) old = v;
        setenv(name.c_str(), value.c_str(), 1);
    }
    ~ScopedEnv() { old ? setenv(name.c_str(), old->c_str(), 1) : unsetenv(name.c_str()); }
};

}  // namespace

TEST_CASE("prepare_output accepts a new folder and changes nothing on disk", "[output][results_folder]") {
    TempDir dir("rf");
    CHECK(refusal(dir.path / "out") == "");
    CHECK(refusal(dir.path / "new" / "deeper" / "out") == "");  // parents can be created
    CHECK(refusal(dir.path / "out/") == "");
    CHECK(fs::is_empty(dir.path));
}

TEST_CASE("prepare_output refuses what coremodal did not write, and it survives", "[output][results_folder]") {
    TempDir dir("rf");
    SECTION("a plain file") {
        write(dir.path / "notes.txt", "mine");
        const std::string why = refusal(dir.path / "notes.txt", true);
        CHECK(why.find("notes.txt' is a file, not a folder") != std::string::npos);
        CHECK(why.find("remove the file yourself") != std::string::npos);
        CHECK(slurp(dir.path / "notes.txt") == "mine");
    }
    SECTION("a folder of the user's files, also with --force") {
        fs::create_directories(dir.path / "thesis");
        write(dir.path / "thesis" / "chapter1.tex", "text");
        for (bool force : {false, true}) {
            const std::string why = refusal(dir.path / "thesis", force);
            CHECK(why.find("thesis' exists and was not written by coremodal (no .coremodal-results") !=
                  std::string::npos);
            CHECK(why.find("choose another folder") != std::string::npos);
        }
        CHECK(slurp(dir.path / "thesis" / "chapter1.tex") == "text");
    }
    SECTION("a symbolic link, even to a coremodal result") {
        fake_result(dir.path / "real", "{}");
        fs::create_directory_symlink(dir.path / "real", dir.path / "link");
        CHECK(refusal(dir.path / "link").find("link' is a symbolic link") != std::string::npos);
    }
    SECTION("a folder whose marker is not coremodal's") {
        fs::create_directories(dir.path / "odd");
        write(dir.path / "odd" / kResultsMarker, "something else\n");
        CHECK(refusal(dir.path / "odd").find("was not written by coremodal") != std::string::npos);
    }
    SECTION("a .previous that is not coremodal's, unless --force (which does not keep one)") {
        fake_result(dir.path / "out", "{}");
        fs::create_directories(dir.path / "out.previous");
        write(dir.path / "out.previous" / "mine.txt", "x");
        CHECK(refusal(dir.path / "out").find("would be kept as '") != std::string::npos);
        CHECK(refusal(dir.path / "out", true) == "");
    }
}

TEST_CASE("prepare_output refuses the working folder, its parents, home and /", "[output][results_folder]") {
    const fs::path cwd = fs::current_path();
    CHECK(refusal(cwd).find("is the working folder") != std::string::npos);
    CHECK(refusal(".").find("is the working folder") != std::string::npos);
    CHECK(refusal("..").find("is a parent of the working folder") != std::string::npos);
    CHECK(refusal(cwd.parent_path()).find("is a parent of the working folder") != std::string::npos);
    CHECK(refusal("/").find("is the root folder") != std::string::npos);
    // Even a home folder that carries the marker.
    TempDir dir("rf");
    fake_result(dir.path / "home", "{}");
    const ScopedEnv home("HOME", (dir.path / "home").string());
    CHECK(refusal(dir.path / "home", true).find("is the home folder") != std::string::npos);
    CHECK(refusal(dir.path / "home/").find("is the home folder") != std::string::npos);
    CHECK(refusal(dir.path).find("is a parent of the home folder") != std::string::npos);
    CHECK(fs::exists(dir.path / "home" / "summary.json"));
}

TEST_CASE("prepare_output refuses a place that cannot be written", "[output][results_folder]") {
    TempDir dir("rf");
    write(dir.path / "afile", "x");
    const std::string under_file = refusal(dir.path / "afile" / "out");
    CHECK(under_file.find("cannot be created") != std::string::npos);
    CHECK(under_file.find("afile' is a file, not a folder") != std::string::npos);
    // sysfs takes no new folders, not even from root (for whom access(2) says yes).
    CHECK(refusal("/sys/coremodal-test-output").find("cannot be written: no folder can be made in '/sys'") !=
          std::string::npos);
}

TEST_CASE("ResultsFolder: complete or not at all, the replaced result kept as .previous", "[output][results_folder]") {
    TempDir dir("rf");
    const fs::path out = dir.path / "out";
    auto write_result = [&](const std::string& content, bool force) {
        ResultsFolder folder(out, force);
        CHECK(fs::exists(folder.dir() / kResultsMarker));
        CHECK(folder.dir().filename().string().rfind("out.partial-", 0) == 0);
        write(folder.file("summary.json"), content);
        folder.commit();
    };
    write_result("first", false);
    CHECK(slurp(out / "summary.json") == "first");
    CHECK(is_results_folder(out));
    CHECK(slurp(out / kResultsMarker).find("coremodal results folder\nversion ") == 0);
    CHECK(marker_host(out) == this_host());
    CHECK_FALSE(fs::exists(previous_path(out)));

    write_result("second", false);
    CHECK(slurp(out / "summary.json") == "second");
    CHECK(slurp(previous_path(out) / "summary.json") == "first");

    write_result("third", false);  // an older .previous of ours is replaced
    CHECK(slurp(previous_path(out) / "summary.json") == "second");

    write_result("fourth", true);  // --force: the old one removed, .previous untouched
    CHECK(slurp(out / "summary.json") == "fourth");
    CHECK(slurp(previous_path(out) / "summary.json") == "second");

    {  // a run that fails before commit leaves the older result as it was
        ResultsFolder folder(out, false);
        write(folder.file("summary.json"), "broken");
    }
    CHECK(slurp(out / "summary.json") == "fourth");
    CHECK(slurp(previous_path(out) / "summary.json") == "second");
    for (const auto& entry : fs::directory_iterator(dir.path)) {
        const std::string name = entry.path().filename().string();
        CHECK((name == "out" || name == "out.previous"));
    }
}

TEST_CASE("An empty folder is taken as the output (nothing to lose) and not kept", "[output][results_folder]") {
    TempDir dir("rf");
    const fs::path out = dir.path / "out";
    fs::create_directories(out);
    CHECK(refusal(out) == "");
    ResultsFolder folder(out, false);
    write(folder.file("summary.json"), "new");
    folder.commit();
    CHECK(slurp(out / "summary.json") == "new");
    CHECK_FALSE(fs::exists(previous_path(out)));
}

TEST_CASE("ResultsFolder refuses a user's file that appeared at the path during the run", "[output][results_folder]") {
    TempDir dir("rf");
    ResultsFolder folder(dir.path / "out", false);
    write(dir.path / "out", "made while the solver ran");
    CHECK_THROWS_WITH(folder.commit(), Catch::Contains("is a file, not a folder"));
    CHECK(slurp(dir.path / "out") == "made while the solver ran");
}

TEST_CASE("Stale partial folders of ended processes on this machine are swept, nothing else",
          "[output][results_folder]") {
    TempDir dir("rf");
    const fs::path out = dir.path / "out";
    const std::string dead = std::to_string(dead_pid());
    const std::string alive = std::to_string(::getppid());
    fake_result(dir.path / ("out.partial-" + dead), "stale");
    fake_result(dir.path / ("out.old-" + dead), "stale");
    fake_result(dir.path / ("out.partial-" + alive), "another run, still going");
    fake_result(dir.path / ("out.partial-" + dead + "x"), "not a process number");
    fake_result(dir.path / ("other.partial-" + dead), "another output's");
    fake_result(dir.path / ("out.partial-999999"), "another machine's", "some-other-host");
    fs::create_directories(dir.path / ("out.partial-1" + dead));  // no marker: not ours
    CHECK(sweep_stale_partials(out) == 2);
    CHECK_FALSE(fs::exists(dir.path / ("out.partial-" + dead)));
    CHECK_FALSE(fs::exists(dir.path / ("out.old-" + dead)));
    for (const std::string& kept : {"out.partial-" + alive, "out.partial-" + dead + "x", "other.partial-" + dead,
                                    std::string("out.partial-999999"), "out.partial-1" + dead})
        CHECK(fs::exists(dir.path / kept));
    // Writing a result sweeps too.
    fake_result(dir.path / ("out.partial-" + dead), "stale");
    ResultsFolder folder(out, false);
    CHECK_FALSE(fs::exists(dir.path / ("out.partial-" + dead)));
}

TEST_CASE("start_folder_in_place: a batch folder with the marker, the older one kept", "[output][results_folder]") {
    TempDir dir("rf");
    const fs::path out = dir.path / "batch";
    start_folder_in_place(out, false, {"batch.csv"});
    CHECK(is_results_folder(out));
    write(out / "batch.csv", "first");
    start_folder_in_place(out, false, {"batch.csv"});
    CHECK(is_results_folder(out));
    CHECK_FALSE(fs::exists(out / "batch.csv"));
    CHECK(slurp(previous_path(out) / "batch.csv") == "first");
    fs::create_directories(dir.path / "mine");
    write(dir.path / "mine" / "notes.txt", "mine");
    CHECK_THROWS_WITH(start_folder_in_place(dir.path / "mine", true), Catch::Contains("was not written by coremodal"));
}

// ---- issue 33 ---------------------------------------------------------------

TEST_CASE("A result's marker lists what coremodal wrote; anything else there keeps it from being replaced",
          "[output][results_folder][issue33]") {
    TempDir dir("rf");
    const fs::path out = dir.path / "out";
    {
        ResultsFolder folder(out, false);
        write(folder.file("summary.json"), "{}");
        fs::create_directories(folder.dir() / "shapes");
        write(folder.dir() / "shapes" / "mode_01.csv", "1");
        folder.commit();
    }
    const std::string marker = slurp(out / kResultsMarker);
    CHECK(marker.find("\ncontents\nwrote shapes\nwrote shapes/mode_01.csv\nwrote summary.json\n") !=
          std::string::npos);
    CHECK(refusal(out) == "");
    SECTION("a user's file, also deep inside and with --force") {
        write(out / "shapes" / "notes.txt", "mine");
        for (bool force : {false, true})
            CHECK(refusal(out, force).find("holds what coremodal did not write into it: 'shapes/notes.txt'") !=
                  std::string::npos);
    }
    SECTION("another results folder inside it, written by a run of its own") {
        {
            ResultsFolder inner(out / "inner", false);
            write(inner.file("summary.json"), "{}");
            inner.commit();
        }
        CHECK(refusal(out, true).find("'inner/' (a results folder of its own)") != std::string::npos);
        CHECK(refusal(out / "inner") == "");  // the inner one is replaceable itself
    }
    SECTION("as the .previous a new result would be rotated over") {
        fake_result(dir.path / "new", "{}");
        write(out / "mine.txt", "x");
        fs::rename(out, previous_path(dir.path / "new"));
        CHECK(refusal(dir.path / "new").find("which holds what coremodal did not write into it: 'mine.txt'") !=
              std::string::npos);
        CHECK(refusal(dir.path / "new", true) == "");  // --force keeps no .previous
    }
    SECTION("an earlier version's marker (no list): only nested results folders count") {
        fake_result(dir.path / "old", "{}");
        write(dir.path / "old" / "extra.csv", "1");
        CHECK(refusal(dir.path / "old") == "");
        fake_result(dir.path / "old" / "nested", "{}");
        CHECK(refusal(dir.path / "old").find("'nested/' (a results folder of its own)") != std::string::npos);
    }
}

TEST_CASE("A batch folder's marker lists its cases: their folders, logs and leftovers are coremodal's",
          "[output][results_folder][issue33]") {
    TempDir dir("rf");
    const fs::path out = dir.path / "batch";
    start_folder_in_place(out, false, {"a/", "a.log", "batch.csv"});
    fake_result(out / "a", "{}");  // the case's own run wrote it
    write(out / "a" / "anything", "x");
    write(out / "a.log", "log");
    fake_result(out / "a.partial-999999", "{}");  // a killed case's partial folder
    write(out / "batch.csv", "table");
    CHECK(refusal(out) == "");
    fake_result(out / "b", "{}");
    CHECK(refusal(out).find("'b/' (a results folder of its own)") != std::string::npos);
}

TEST_CASE("claim_output takes the output's lock once per process and says who holds it",
          "[output][results_folder][issue33]") {
    TempDir dir("rf");
    const fs::path out = dir.path / "deeper" / "out";
    claim_output(out, false);
    claim_output(out, false);  // this process holds it: a check only
    const std::string lock = slurp(dir.path / "deeper" / "out.lock");
    CHECK(lock.find("pid " + std::to_string(::getpid()) + "\nhost " + this_host() + "\nstarted ") == 0);
    // A ResultsFolder of the claimed output does not release the claim.
    {
        ResultsFolder folder(out, false);
        folder.commit();
    }
    CHECK(fs::exists(dir.path / "deeper" / "out.lock"));
    // One it took itself it releases, lock file and all.
    {
        ResultsFolder folder(dir.path / "other", false);
        CHECK(fs::exists(dir.path / "other.lock"));
    }
    CHECK_FALSE(fs::exists(dir.path / "other.lock"));
}

TEST_CASE("A lock left by a SIGKILLed run is taken over by the next run, which says whose it was (issue 33, 10)",
          "[output][results_folder][lock][issue33]") {
    TempDir dir("rf");
    const fs::path out = dir.path / "out", lock = dir.path / "out.lock";
    // A run that took the lock and was killed before releasing it.
    const pid_t killed = ::fork();
    if (killed == 0) {
        try {
            claim_output(out, false);
        } catch (...) {
            ::_exit(3);
        }
        ::raise(SIGKILL);
        ::_exit(4);
    }
    int status = 0;
    ::waitpid(killed, &status, 0);
    REQUIRE(WIFSIGNALED(status));
    REQUIRE(WTERMSIG(status) == SIGKILL);
    REQUIRE(slurp(lock).find("pid " + std::to_string(killed) + "\n") == 0);  // left behind

    std::ostringstream said;
    std::streambuf* const stderr_buffer = std::cerr.rdbuf(said.rdbuf());
    try {
        ResultsFolder folder(out, false);  // not refused: the kernel released the dead run's flock
        write(folder.file("a.txt"), "x");
        folder.commit();
    } catch (...) {
        std::cerr.rdbuf(stderr_buffer);
        throw;
    }
    std::cerr.rdbuf(stderr_buffer);
    INFO(said.str());
    CHECK(said.str().find("'" + lock.string() + "' was left by pid " + std::to_string(killed) + " on " + this_host()) !=
          std::string::npos);
    CHECK(said.str().find("which no longer runs (killed?); its lock was free, this run has taken it over") !=
          std::string::npos);
    CHECK(fs::exists(out / "a.txt"));
    CHECK_FALSE(fs::exists(lock));  // the taker removed it when done

    // A lock released normally leaves nothing to take over: no note.
    std::ostringstream quiet;
    std::cerr.rdbuf(quiet.rdbuf());
    try {
        ResultsFolder folder(dir.path / "other", false);
    } catch (...) {
        std::cerr.rdbuf(stderr_buffer);
        throw;
    }
    std::cerr.rdbuf(stderr_buffer);
    CHECK(quiet.str().empty());
}

TEST_CASE("A text file that cannot be written whole is an error, not 0 bytes (issue 33, 6)",
          "[output][results_folder][issue33]") {
    // /dev/full takes the open and fails every write with ENOSPC, as a full disk does.
    CHECK_THROWS_WITH(write_text_file("/dev/full", "batch table\n"),
                      Catch::Contains("cannot write /dev/full (No space left on device)"));
}
