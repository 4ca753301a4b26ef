// Never lose a user's data, never leave debris (issue 11, defects 1 and 2):
// the real program with --output at the user's files and folders, at the
// working folder's parent, at a place it cannot write; an earlier result
// replaced and kept; SIGINT and SIGTERM in the middle of a run and of a
// batch; a partial folder left by a killed run swept by the next.
#include "support/program_run.hpp"
#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

// The same tube with 2 x 16 x 40 hex20 (about 40 000 DOFs): a solve of a
// few seconds, long enough to be interrupted in.
std::string slow_case() {
    std::string text = kTinyCase;
    const std::string mesh = "around = 8\nalong = 4\nthrough_wall = 1";
    text.replace(text.find(mesh), mesh.size(), "around = 16\nalong = 40\nthrough_wall = 2");
    return text;
}

// What a [study] or [calibration] table adds to the tiny case.
const std::string kStudyTable = R"(
[study]
modes = 6
parameters = [{ key = "core.length", values = ["0.5 m", "0.6 m"] }]
)";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The folders and partial folders a run left in `folder`.
std::set<std::string> folders_in(const fs::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.is_directory()) names.insert(entry.path().filename().string());
    return names;
}

bool any_partial(const fs::path& folder) {
    for (const std::string& name : folders_in(folder))
        if (contains(name, ".partial-")) return true;
    return false;
}

bool process_gone(pid_t pid) { return ::kill(pid, 0) != 0 && errno == ESRCH; }

// The study workers whose parent is `study` (from /proc/<pid>/stat: "pid
// (name) state ppid ..."; an MPI singleton has other children, e.g. orted).
std::vector<pid_t> workers_of(pid_t study) {
    std::vector<pid_t> workers;
    for (const auto& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const std::string stat = slurp(entry.path() / "stat");
        const size_t end_of_name = stat.rfind(')');
        if (end_of_name == std::string::npos) continue;
        std::istringstream rest(stat.substr(end_of_name + 1));
        std::string state;
        pid_t ppid = 0;
        if (rest >> state >> ppid && ppid == study && contains(slurp(entry.path() / "cmdline"), "--worker-point"))
            workers.push_back(std::stoi(name));
    }
    return workers;
}

// A stand-in for python3 that never finishes a picture: it notes its own
// process number and its parent's (the coremodal that started it) in
// dir/pids/, then sleeps. With it a run is sure to be in its writing step,
// its partial folder on disk, when the test sends a signal.
std::string sleeping_python(const TempDir& dir) {
    const fs::path script = dir.path / "slow-python";
    const fs::path pids = dir.path / "pids";
    fs::create_directories(pids);
    const std::string folder = pids.string();  // in double quotes below: $$ is expanded
    std::ofstream(script) << "#!/bin/sh\necho \"$$ $PPID\" > \"" << folder << "/.$$\" && mv \"" << folder
                          << "/.$$\" \"" << folder << "/$$\"\nexec sleep 120\n";
    fs::permissions(script, fs::perms::owner_all);
    return "COREMODAL_PYTHON='" + script.string() + "'";
}

// The (python, its parent coremodal) process numbers the stand-in noted.
std::vector<std::pair<pid_t, pid_t>> sleeping_pythons(const TempDir& dir) {
    std::vector<std::pair<pid_t, pid_t>> found;
    for (const auto& entry : fs::directory_iterator(dir.path / "pids")) {
        if (entry.path().filename().string()[0] == '.') continue;
        std::ifstream in(entry.path());
        pid_t python = 0, parent = 0;
        if (in >> python >> parent) found.emplace_back(python, parent);
    }
    return found;
}

// Runs `coremodal args` with the sleeping python, waits until `ready(pid)`
// (at most ready_s), then sends `sig` to coremodal (to its whole process
// group with SIGKILL: no child outlives it), and returns how it ended.
template <class Ready>
Run interrupted(const TempDir& dir, const std::string& args, Ready ready, double ready_s, int sig) {
    Started started = start_coremodal(dir, args, sleeping_python(dir));
    REQUIRE(wait_until([&] { return ready(started.pid); }, ready_s));
    ::kill(sig == SIGKILL ? -started.pid : started.pid, sig);
    const std::optional<Run> r = finish_coremodal(dir, started, 40);  // the children's grace is 10 s
    REQUIRE(r);
    return *r;
}

// The message of a refused output: the path, why and what to do.
void check_refused(const Run& r, const std::string& path, const std::string& why) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.err, "output folder '" + path + "' " + why));
    CHECK((contains(r.err, "choose another folder") || contains(r.err, "choose a folder you can write to")));
    CHECK_FALSE(contains(r.out, "meshing"));  // refused before any work
}

}  // namespace

TEST_CASE("run --output never replaces the user's file or folder", "[app][output_safety]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    SECTION("a plain file") {
        dir.write("notes.txt", "my notes");
        check_refused(run_coremodal(dir, "run tiny.toml --output notes.txt --no-plots"), "notes.txt",
                      "is a file, not a folder");
        CHECK(slurp(dir.path / "notes.txt") == "my notes");
    }
    SECTION("a folder of the user's files, with or without --force") {
        fs::create_directories(dir.path / "thesis" / "figures");
        dir.write("thesis/chapter1.tex", "text");
        for (const char* force : {"", " --force"}) {
            check_refused(run_coremodal(dir, std::string("run tiny.toml --output thesis --no-plots") + force),
                          "thesis", "exists and was not written by coremodal");
            CHECK(slurp(dir.path / "thesis" / "chapter1.tex") == "text");
            CHECK(fs::is_directory(dir.path / "thesis" / "figures"));
        }
    }
    SECTION("the default results/<name> when the user has a folder there") {
        fs::create_directories(dir.path / "results" / "tiny");
        dir.write("results/tiny/data.csv", "1,2");
        check_refused(run_coremodal(dir, "run tiny.toml --no-plots"), "results/tiny",
                      "exists and was not written by coremodal");
        CHECK(slurp(dir.path / "results" / "tiny" / "data.csv") == "1,2");
    }
    SECTION("a symbolic link to a folder") {
        fs::create_directories(dir.path / "real");
        fs::create_directory_symlink(dir.path / "real", dir.path / "link");
        check_refused(run_coremodal(dir, "run tiny.toml --output link --no-plots"), "link", "is a symbolic link");
    }
}

TEST_CASE("run --output refuses the working folder, its parents and the home folder", "[app][output_safety]") {
    TempDir dir("safety");
    fs::create_directories(dir.path / "work");
    fs::create_directories(dir.path / "home");
    dir.write("work/tiny.toml", kTinyCase);
    dir.write("home/.profile", "keep me");
    const std::string in_work = "-C work";  // env's option: run in dir/work
    check_refused(run_coremodal(dir, "run tiny.toml --output .. --no-plots", in_work), "..",
                  "is a parent of the working folder");
    check_refused(run_coremodal(dir, "run tiny.toml --output . --no-plots --force", in_work), ".",
                  "is the working folder");
    check_refused(run_coremodal(dir, "run tiny.toml --output '" + dir.path.string() + "/' --no-plots", in_work),
                  dir.path.string(), "is a parent of the working folder");
    // `--output ~` as the shell expands it.
    const std::string home = (dir.path / "home").string();
    check_refused(run_coremodal(dir, "run tiny.toml --output " + home + " --no-plots", in_work + " HOME=" + home),
                  home, "is the home folder");
    CHECK(slurp(dir.path / "home" / ".profile") == "keep me");
    CHECK(fs::exists(dir.path / "work" / "tiny.toml"));
    CHECK(folders_in(dir.path) == std::set<std::string>{"home", "work"});
}

TEST_CASE("An unwritable output place is refused before meshing and solving", "[app][output_safety]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    dir.write("afile", "x");
    check_refused(run_coremodal(dir, "run tiny.toml --output afile/out --no-plots"), "afile/out", "cannot be created");
    const Run r = run_coremodal(dir, "run tiny.toml --output /sys/coremodal-test/out --no-plots");
    check_refused(r, "/sys/coremodal-test/out", "cannot be written");
    CHECK_FALSE(contains(r.err, "filesystem error"));
}

TEST_CASE("An earlier result is replaced and kept as .previous; --force keeps none", "[app][output_safety]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    const Run first = run_coremodal(dir, "run tiny.toml -o out -q --no-plots");
    REQUIRE(first.exit_code == 0);
    const fs::path marker = dir.path / "out" / ".coremodal-results";
    REQUIRE(fs::exists(marker));
    CHECK(contains(slurp(marker), "command "));
    CHECK(contains(slurp(marker), "run tiny.toml -o out"));
    dir.write("out/first.txt", "from the first run");  // to tell the results apart

    const Run second = run_coremodal(dir, "run tiny.toml -o out -q --no-plots");
    REQUIRE(second.exit_code == 0);
    CHECK(fs::exists(dir.path / "out" / "summary.json"));
    CHECK_FALSE(fs::exists(dir.path / "out" / "first.txt"));
    CHECK(slurp(dir.path / "out.previous" / "first.txt") == "from the first run");
    CHECK(fs::exists(dir.path / "out.previous" / "summary.json"));

    dir.write("out/second.txt", "");
    const Run forced = run_coremodal(dir, "run tiny.toml -o out -q --no-plots --force");
    REQUIRE(forced.exit_code == 0);
    CHECK_FALSE(fs::exists(dir.path / "out" / "second.txt"));
    CHECK(fs::exists(dir.path / "out.previous" / "first.txt"));  // --force leaves .previous alone
    CHECK(folders_in(dir.path) == std::set<std::string>{"out", "out.previous"});
}

TEST_CASE("study, calibrate, converge and batch refuse the user's folder before any work", "[app][output_safety]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    dir.write("study.toml", kTinyCase + kStudyTable);
    std::string calibration = kStudyTable;
    calibration.replace(calibration.find("[study]"), 7, "[calibration]");
    dir.write("cal.toml", kTinyCase + calibration);
    fs::create_directories(dir.path / "mine");
    dir.write("mine/keep.txt", "mine");
    for (const std::string command : {"study study.toml", "calibrate cal.toml", "converge tiny.toml",
                                      "batch tiny.toml"}) {
        INFO(command);
        const Run r = run_coremodal(dir, command + " --output mine");
        check_refused(r, "mine", "exists and was not written by coremodal");
        CHECK(r.out.empty());  // not even the first progress line
        CHECK(slurp(dir.path / "mine" / "keep.txt") == "mine");
    }
    CHECK(folders_in(dir.path) == std::set<std::string>{"mine"});
}

TEST_CASE("A stale partial folder of a run that was killed is swept by the next run", "[app][output_safety]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    // A run killed with SIGKILL while writing: its partial folder, its marker.
    const auto writing = [&](pid_t) { return !sleeping_pythons(dir).empty(); };
    interrupted(dir, "run tiny.toml -o out -q", writing, 120, SIGKILL);
    REQUIRE(any_partial(dir.path));
    // A user's folder of the same pattern without the marker is not touched.
    fs::create_directories(dir.path / "out.partial-999999");
    const Run r = run_coremodal(dir, "run tiny.toml -o out -q --no-plots");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(folders_in(dir.path) == std::set<std::string>{"out", "out.partial-999999", "pids"});
}

TEST_CASE("SIGINT while writing stops python, removes the partial folder, exits 130", "[app][output_safety][signals]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    const auto writing = [&](pid_t) { return !sleeping_pythons(dir).empty() && any_partial(dir.path); };
    const Run r = interrupted(dir, "run tiny.toml -o out", writing, 120, SIGINT);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 130);
    CHECK(contains(r.err, "coremodal: interrupted by SIGINT; stopped 1 child process(es); removed out.partial-"));
    CHECK(process_gone(sleeping_pythons(dir).at(0).first));
    CHECK_FALSE(any_partial(dir.path));
    CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("SIGHUP and SIGQUIT while writing end the run as SIGINT does, exit 128 + signal", "[app][output_safety][signals]") {
    // Issue 33, item 10: PETSc's "Caught signal" dump (exit 59), the partial
    // folder and the python child left behind.
    const auto [sig, name] = GENERATE(std::pair{SIGHUP, "SIGHUP"}, std::pair{SIGQUIT, "SIGQUIT"});
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    const auto writing = [&](pid_t) { return !sleeping_pythons(dir).empty() && any_partial(dir.path); };
    const Run r = interrupted(dir, "run tiny.toml -o out", writing, 120, sig);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 128 + sig);
    CHECK(contains(r.err, std::string("coremodal: interrupted by ") + name +
                              "; stopped 1 child process(es); removed out.partial-"));
    CHECK_FALSE(contains(r.err, "Caught signal"));
    CHECK(process_gone(sleeping_pythons(dir).at(0).first));
    CHECK_FALSE(any_partial(dir.path));
    CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("A reader that stops reading (run | head -2) ends the run quietly with 141", "[app][output_safety][signals]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    // The shell's pipe: head takes the first two progress lines and leaves;
    // coremodal's next line meets a closed pipe. ${PIPESTATUS[0]}: its status.
    // SIGPIPE as a shell gives it (the test binary may have it ignored).
    const std::string command = coremodal_command(dir, "run tiny.toml -o out --no-plots", "--default-signal=PIPE");
    const std::string piped = command.substr(0, command.rfind(" >stdout.txt")) + " 2>stderr.txt | head -2 >stdout.txt";
    const std::string script = dir.path.string() + "/piped.sh";
    dir.write("piped.sh", piped + "\necho ${PIPESTATUS[0]} > '" + dir.path.string() + "/status.txt'\n");
    REQUIRE(std::system(("bash '" + script + "'").c_str()) == 0);
    const std::string err = slurp(dir.path / "stderr.txt");
    INFO("stderr: " << err);
    CHECK(std::stoi(slurp(dir.path / "status.txt")) == 128 + SIGPIPE);
    CHECK(err.empty());  // quietly: no dump, no message
    CHECK_FALSE(any_partial(dir.path));
    CHECK_FALSE(fs::exists(dir.path / "out" / "summary.json"));
}

TEST_CASE("SIGTERM during the solve exits 143 and writes nothing", "[app][output_safety][signals]") {
    TempDir dir("safety");
    dir.write("slow.toml", slow_case());
    const auto solving = [&](pid_t) { return contains(slurp(dir.path / "stdout.txt"), "[4/7] solving"); };
    const Run r = interrupted(dir, "run slow.toml -o out", solving, 120, SIGTERM);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 143);
    CHECK(contains(r.err, "coremodal: interrupted by SIGTERM"));
    CHECK(folders_in(dir.path) == std::set<std::string>{"pids"});
}

TEST_CASE("batch passes SIGTERM on to its cases and waits for them", "[app][output_safety][signals]") {
    TempDir dir("safety");
    fs::create_directories(dir.path / "cases");
    dir.write("cases/a.toml", kTinyCase);
    dir.write("cases/b.toml", kTinyCase);
    const auto both_writing = [&](pid_t) { return sleeping_pythons(dir).size() == 2; };
    const Run r = interrupted(dir, "batch cases --jobs 2 -o out", both_writing, 180, SIGTERM);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 143);
    CHECK(contains(r.err, "coremodal: interrupted by SIGTERM; stopped 2 child process(es)"));
    for (const auto& [python, run] : sleeping_pythons(dir)) {
        CHECK(process_gone(python));
        CHECK(process_gone(run));
    }
    CHECK_FALSE(any_partial(dir.path / "out"));
    CHECK_FALSE(fs::exists(dir.path / "out" / "batch.csv"));  // no table of stopped cases
    CHECK(contains(slurp(dir.path / "out" / "a.log"), "coremodal: interrupted by SIGTERM"));
}

TEST_CASE("study passes SIGTERM on to its workers and removes its scratch folder", "[app][output_safety][signals]") {
    TempDir dir("safety");
    dir.write("study.toml", slow_case() + kStudyTable);
    std::vector<pid_t> workers;
    fs::path scratch;
    const auto both_running = [&](pid_t study) {
        workers = workers_of(study);
        scratch = fs::temp_directory_path() / ("coremodal-study-" + std::to_string(study));
        return workers.size() == 2;
    };
    const Run r = interrupted(dir, "study study.toml --jobs 2 -o out", both_running, 180, SIGTERM);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 143);
    CHECK(contains(r.err, "coremodal: interrupted by SIGTERM; stopped 2 child process(es); removed " +
                              scratch.string()));
    for (pid_t worker : workers) CHECK(process_gone(worker));
    CHECK_FALSE(fs::exists(scratch));
    CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("A study killed with SIGKILL takes its workers with it; the next study sweeps its scratch folder",
          "[app][output_safety][signals]") {
    // Issue 33, item 10: after SIGKILL the workers ran on as orphans and
    // /tmp/coremodal-study-PID stayed.
    TempDir dir("safety");
    dir.write("study.toml", slow_case() + kStudyTable);
    std::vector<pid_t> workers;
    fs::path scratch;
    const auto both_running = [&](pid_t study) {
        workers = workers_of(study);
        scratch = fs::temp_directory_path() / ("coremodal-study-" + std::to_string(study));
        return workers.size() == 2;
    };
    interrupted(dir, "study study.toml --jobs 2 -o out", both_running, 180, SIGKILL);
    // The kernel passes the study's death on as SIGTERM; a worker removes
    // what it wrote and ends within its grace.
    for (pid_t worker : workers) CHECK(wait_until([&] { return process_gone(worker); }, 20));
    REQUIRE(fs::exists(scratch));  // SIGKILL: the study could not remove it
    // The scratch folder of a live coremodal (this test binary's own number)
    // is not touched.
    const fs::path live = fs::temp_directory_path() / ("coremodal-study-" + std::to_string(::getpid()));
    fs::create_directories(live);
    dir.write("tiny-study.toml", kTinyCase + kStudyTable);
    const Run r = run_coremodal(dir, "study tiny-study.toml --jobs 2 -o next -q --no-plots");
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 0);
    CHECK_FALSE(fs::exists(scratch));
    CHECK(fs::exists(live));
    fs::remove_all(live);
}
