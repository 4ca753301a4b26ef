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
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <map>
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
    // To tell the results apart, a word in a file the run wrote (a file of
    // the user's added would keep the folder from being replaced: issue 33).
    const auto mark = [&](const std::string& word) { std::ofstream(dir.path / "out" / "modes.csv", std::ios::app) << word; };
    mark("first");

    const Run second = run_coremodal(dir, "run tiny.toml -o out -q --no-plots");
    REQUIRE(second.exit_code == 0);
    CHECK(fs::exists(dir.path / "out" / "summary.json"));
    CHECK_FALSE(contains(slurp(dir.path / "out" / "modes.csv"), "first"));
    CHECK(contains(slurp(dir.path / "out.previous" / "modes.csv"), "first"));
    CHECK(fs::exists(dir.path / "out.previous" / "summary.json"));

    mark("second");
    const Run forced = run_coremodal(dir, "run tiny.toml -o out -q --no-plots --force");
    REQUIRE(forced.exit_code == 0);
    CHECK_FALSE(contains(slurp(dir.path / "out" / "modes.csv"), "second"));
    CHECK(contains(slurp(dir.path / "out.previous" / "modes.csv"), "first"));  // --force leaves .previous alone
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
    // Quietly: no dump, no message of its own — the case's warnings, written
    // before the pipe closed (the tiny case's mesh is coarser than its band), may stand.
    std::istringstream lines(err);
    for (std::string line; std::getline(lines, line);) CHECK(line.rfind("coremodal: warning: ", 0) == 0);
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

// ---- issue 33: nothing a user owns is ever lost ---------------------------

namespace {

const std::string kCase02 = std::string(COREMODAL_SOURCE_DIR) + "/cases/02-clamped-76x15.toml";
const std::string kCase05 = std::string(COREMODAL_SOURCE_DIR) + "/cases/05-beam-level-rest-roll-150x15.8-4320.toml";
const std::string kCase11 = std::string(COREMODAL_SOURCE_DIR) + "/cases/11-two-drum-winder.toml";
const std::string kCase12 = std::string(COREMODAL_SOURCE_DIR) + "/cases/12-rotation-tester-76x15.toml";
const std::string kCase13 =
    std::string(COREMODAL_SOURCE_DIR) + "/cases/13-rest-roll-response-150x15.8-4320.toml";
const std::string kMpirun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 2 --oversubscribe ";

// Every file under `folder` with its content: what "nothing changed" compares.
std::map<std::string, std::string> snapshot(const fs::path& folder) {
    std::map<std::string, std::string> files;
    if (!fs::exists(folder)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) files[fs::relative(entry.path(), folder).string()] = slurp(entry.path());
    return files;
}

// `case_text` with its name line replaced by `name_line`.
std::string renamed(std::string case_text, const std::string& name_line) {
    const size_t end = case_text.find('\n');
    return case_text.replace(0, end, name_line);
}

}  // namespace

TEST_CASE("A results folder holding another case's results and the user's notes is never replaced (issue 33, 1)",
          "[app][output_safety][issue33]") {
    TempDir dir("safety");
    // The exact sequence of the issue, case 02 at the beam level to stay fast.
    REQUIRE(run_coremodal(dir, "run '" + kCase05 + "' -o results -q --no-plots").exit_code == 0);
    REQUIRE(run_coremodal(dir, "run '" + kCase02 + "' --model beam -q --no-plots").exit_code == 0);
    const fs::path inner = dir.path / "results" / "02-clamped-76x15";
    REQUIRE(fs::exists(inner / "summary.json"));
    dir.write("results/02-clamped-76x15/notes.txt", "my notes");
    const auto before = snapshot(dir.path / "results");
    for (const char* force : {"", " --force"}) {
        INFO("force: '" << force << "'");
        const Run r = run_coremodal(dir, "run '" + kCase05 + "' -o results -q --no-plots" + std::string(force));
        INFO("stderr: " << r.err);
        CHECK(r.exit_code == 1);
        CHECK(contains(r.err, "output folder 'results' holds what coremodal did not write into it: "
                              "'02-clamped-76x15/' (a results folder of its own)"));
        CHECK(contains(r.err, "move those out yourself, or choose another folder"));
        CHECK(snapshot(dir.path / "results") == before);
        CHECK_FALSE(fs::exists(dir.path / "results.previous"));
    }
    // A user's file added to a result of its own keeps it too; its own files do not.
    REQUIRE(run_coremodal(dir, "run '" + kCase05 + "' -o solo -q --no-plots").exit_code == 0);
    REQUIRE(run_coremodal(dir, "run '" + kCase05 + "' -o solo -q --no-plots").exit_code == 0);  // replaces
    dir.write("solo/notes.txt", "mine");
    const Run kept = run_coremodal(dir, "run '" + kCase05 + "' -o solo -q --no-plots --force");
    CHECK(kept.exit_code == 1);
    CHECK(contains(kept.err, "output folder 'solo' holds what coremodal did not write into it: 'notes.txt'"));
    CHECK(slurp(dir.path / "solo" / "notes.txt") == "mine");
    // ... and keeps the .previous it would otherwise be rotated over.
    fs::remove(dir.path / "solo" / "notes.txt");
    dir.write("solo.previous/notes.txt", "mine too");
    const Run previous = run_coremodal(dir, "run '" + kCase05 + "' -o solo -q --no-plots");
    CHECK(previous.exit_code == 1);
    CHECK(contains(previous.err, "would be kept as 'solo.previous', which holds what coremodal did not write into "
                                 "it: 'notes.txt'"));
    CHECK(slurp(dir.path / "solo.previous" / "notes.txt") == "mine too");
}

TEST_CASE("A case name that is empty, '.' or a path is refused before any work (issue 33, 1 and 3)",
          "[app][output_safety][issue33]") {
    TempDir dir("safety");
    // An earlier result in results/ that a name "" or "." would have rotated away.
    REQUIRE(run_coremodal(dir, "run '" + kCase05 + "' -q --no-plots").exit_code == 0);
    const auto before = snapshot(dir.path);
    struct Bad {
        std::string line, why;
    };
    for (const Bad& bad : {Bad{"name = \"\"", "is empty"}, Bad{"name = \".\"", "is '.'"},
                           Bad{"name = \"../../x\"", "is a path, not a name"},
                           Bad{"name = \"/tmp/abs\"", "is a path, not a name"}}) {
        INFO(bad.line);
        std::string text = slurp(kCase05);
        const std::string original = "name = \"05-beam-level-rest-roll-150x15.8-4320\"";
        REQUIRE(text.find(original) != std::string::npos);
        text.replace(text.find(original), original.size(), bad.line);
        dir.write("bad.toml", text);
        for (const std::string command : {"run bad.toml --force --no-plots", "check bad.toml"}) {
            const Run r = run_coremodal(dir, command);
            INFO(command << "\nstdout: " << r.out << "\nstderr: " << r.err);
            CHECK(r.exit_code == 1);
            CHECK(contains(r.err, "bad.toml:61:8: " + bad.line + " " + bad.why));
            CHECK(contains(r.err, "expected a plain name"));
        }
        fs::remove(dir.path / "bad.toml");
        CHECK(snapshot(dir.path) == before);
    }
    CHECK_FALSE(fs::exists("/tmp/abs"));
    CHECK_FALSE(fs::exists(dir.path.parent_path().parent_path() / "x"));
}

TEST_CASE("schema --output never overwrites a user's file nor writes through a link (issue 33, 2)",
          "[app][output_safety][issue33]") {
    TempDir dir("safety");
    dir.write("case.toml", kTinyCase);
    fs::create_symlink(dir.path / "case.toml", dir.path / "link.json");
    const Run file = run_coremodal(dir, "schema --output case.toml");
    CHECK(file.exit_code == 1);
    CHECK(contains(file.err, "schema output 'case.toml' exists and is not a schema coremodal wrote"));
    const Run link = run_coremodal(dir, "schema --output link.json");
    CHECK(link.exit_code == 1);
    CHECK(contains(link.err, "schema output 'link.json' is a symbolic link"));
    CHECK(slurp(dir.path / "case.toml") == kTinyCase);
    CHECK(fs::is_symlink(dir.path / "link.json"));
    // A new file is written, and so is one coremodal wrote before; nothing else is left.
    REQUIRE(run_coremodal(dir, "schema --output case.schema.json").exit_code == 0);
    const std::string schema = slurp(dir.path / "case.schema.json");
    CHECK(contains(schema, "\"coremodal case file\""));
    REQUIRE(run_coremodal(dir, "schema --output case.schema.json").exit_code == 0);
    CHECK(slurp(dir.path / "case.schema.json") == schema);
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.path)) names.insert(entry.path().filename().string());
    CHECK(names == std::set<std::string>{"case.schema.json", "case.toml", "link.json"});
}

TEST_CASE("Under mpirun -n 2 the commands that run in one process refuse, the earlier result stays (issue 33, 4)",
          "[app][output_safety][issue33][mpi]") {
    TempDir dir("safety");
    dir.write("batch.toml", renamed(kTinyCase, "name = \"b\""));
    // An earlier result (any of coremodal's may be replaced by any command), copied to every output.
    REQUIRE(run_coremodal(dir, "run '" + kCase05 + "' -o earlier -q --no-plots").exit_code == 0);
    const auto earlier = snapshot(dir.path / "earlier");
    struct Trial {
        std::string args, folder;
    };
    for (const Trial& t : {Trial{"campbell '" + kCase12 + "' --model beam --no-plots", "campbell"},
                           Trial{"response '" + kCase13 + "' --model beam --no-plots", "response"},
                           Trial{"response '" + kCase13 + "' --model harmonic --no-plots", "response-h"},
                           Trial{"winder '" + kCase11 + "' --no-plots", "winder"},
                           Trial{"batch batch.toml --mesh coarse", "batch"}}) {
        INFO(t.args);
        fs::copy(dir.path / "earlier", dir.path / t.folder, fs::copy_options::recursive);
        const Run r = run_coremodal(dir, t.args + " -o " + t.folder, kMpirun);
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        CHECK(r.exit_code != 0);
        CHECK(contains(r.err, "runs in one process"));
        CHECK(contains(r.err, "run it without mpirun"));
        CHECK(snapshot(dir.path / t.folder) == earlier);
        CHECK_FALSE(fs::exists(dir.path / (t.folder + ".previous")));
    }
}

TEST_CASE("Two runs into one --output: the second is refused naming the first, whose result survives (issue 33, 5)",
          "[app][output_safety][issue33]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    REQUIRE(run_coremodal(dir, "run tiny.toml -o out -q --no-plots").exit_code == 0);
    const auto earlier = snapshot(dir.path / "out");
    // The first run holds the folder while it writes (the sleeping python keeps it there).
    Started first = start_coremodal(dir, "run tiny.toml -o out -q", sleeping_python(dir));
    REQUIRE(wait_until([&] { return !sleeping_pythons(dir).empty(); }, 120));
    TempDir other("safety");
    other.write("tiny.toml", kTinyCase);
    const std::string out = (dir.path / "out").string();
    for (const std::string command : {"run tiny.toml", "run tiny.toml --force", "converge tiny.toml"}) {
        const Run second = run_coremodal(other, command + " -o '" + out + "' -q --no-plots");
        INFO(command << "\nstderr: " << second.err);
        CHECK(second.exit_code == 1);
        CHECK(contains(second.err, "is being written by another coremodal run (pid " + std::to_string(first.pid) +
                                       " on "));
        CHECK(contains(second.err, "run tiny.toml -o out -q"));
        CHECK(contains(second.err, "wait until it has finished, or choose another folder"));
    }
    CHECK(snapshot(dir.path / "out") == earlier);
    // A run killed while holding the lock does not block the next (the kernel released it).
    ::kill(-first.pid, SIGKILL);
    REQUIRE(finish_coremodal(dir, first, 20));
    const Run next = run_coremodal(dir, "run tiny.toml -o out -q --no-plots");
    INFO("stderr: " << next.err);
    CHECK(next.exit_code == 0);
    CHECK(fs::exists(dir.path / "out" / "summary.json"));
    CHECK(snapshot(dir.path / "out.previous") == earlier);
    CHECK_FALSE(fs::exists(dir.path / "out.lock"));  // the next run took it over and removed it
}

namespace {

// A tmpfs of `size` mounted at `dir` for the test's lifetime (root only; the
// test is skipped with the reason where mount is not allowed).
struct SmallDisk {
    fs::path dir;
    bool mounted = false;
    SmallDisk(fs::path d, const std::string& size) : dir(std::move(d)) {
        fs::create_directories(dir);
        mounted = std::system(("mount -t tmpfs -o size=" + size + " tmpfs '" + dir.string() + "' 2>/dev/null").c_str()) == 0;
    }
    ~SmallDisk() {
        if (mounted) std::system(("umount '" + dir.string() + "'").c_str());
    }
    // Fills the disk but `left` bytes (a filler file).
    void fill_but(unsigned long left) const {
        struct statvfs s {};
        REQUIRE(::statvfs(dir.c_str(), &s) == 0);
        const unsigned long free_bytes = s.f_bavail * s.f_frsize;
        std::ofstream filler(dir / "filler", std::ios::binary);
        const std::string block(free_bytes > left ? free_bytes - left : 0, '\0');
        filler << block;
    }
    void empty() const { fs::remove(dir / "filler"); }
};

}  // namespace

TEST_CASE("A full disk is a clean error: no crash, no partial folder, and the next batch works (issue 33, 6)",
          "[app][output_safety][issue33][disk]") {
    TempDir dir("safety");
    dir.write("tiny.toml", kTinyCase);
    const SmallDisk disk(dir.path / "disk", "1m");
    if (!disk.mounted) {
        WARN("skipped: mount -t tmpfs is not allowed here (the test needs root)");
        return;
    }
    dir.write("disk/notes.txt", "the user's notes");
    SECTION("the harmonic level: HDF5 failed and then crashed in MPI_Finalize (exit 139)") {
        // Room for the marker, summary.json and modes.csv (about 16 kB), not for modes.h5 (185 kB).
        disk.fill_but(64 * 1024);
        const Run r = run_coremodal(dir, "run tiny.toml --model harmonic -o disk/out -q --no-plots");
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        CHECK(r.exit_code == 1);
        CHECK(contains(r.err, "modes.h5 (No space left on device)"));
        CHECK_FALSE(any_partial(disk.dir));
        CHECK_FALSE(fs::exists(disk.dir / "out"));
    }
    SECTION("batch: no 0-byte marker or tables reported as written, and the next batch works") {
        disk.fill_but(0);
        const Run full = run_coremodal(dir, "batch tiny.toml -o disk/b --mesh coarse");
        INFO("stdout: " << full.out << "\nstderr: " << full.err);
        CHECK(full.exit_code == 1);
        CHECK(contains(full.err, ".coremodal-results (No space left on device)"));
        CHECK_FALSE(contains(full.out, "table: "));
        CHECK_FALSE(fs::exists(disk.dir / "b"));
        disk.empty();
        const Run next = run_coremodal(dir, "batch tiny.toml -o disk/b --mesh coarse", "COREMODAL_PYTHON=/nonexistent");
        INFO("stdout: " << next.out << "\nstderr: " << next.err);
        CHECK(next.exit_code == 0);
        CHECK(slurp(disk.dir / "b" / "batch.csv").size() > 0);
    }
    CHECK(slurp(disk.dir / "notes.txt") == "the user's notes");
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
