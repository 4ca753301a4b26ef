// A mistyped command line, as a new user types it: the message names what
// was typed, suggests the nearest valid word and lists the valid ones
// (issue 11, defect 5); `--version` says which build this is.
#include "support/program_run.hpp"
#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

using namespace coremodal::testing;

TEST_CASE("An unknown command is named, with the commands that exist", "[app][cli]") {
    TempDir dir;
    SECTION("a word that is no command") {
        const Run r = run_coremodal(dir, "frobnicate case.toml");
        CHECK(r.exit_code == 64);  // EX_USAGE (app/commands.hpp kExitUsage)
        CHECK_THAT(r.err, Catch::Contains("unknown command 'frobnicate'"));
        for (const char* command : {"run", "check", "beam", "batch", "converge", "study", "calibrate"})
            CHECK_THAT(r.err, Catch::Contains(command));
        // Before: CLI11's "A subcommand is required", which names nothing.
        CHECK_THAT(r.err, !Catch::Contains("A subcommand is required"));
    }
    SECTION("a misspelt command gets the nearest one") {
        const Run r = run_coremodal(dir, "chekc case.toml");
        CHECK(r.exit_code == 64);  // EX_USAGE (app/commands.hpp kExitUsage)
        CHECK_THAT(r.err, Catch::Contains("unknown command 'chekc'; did you mean 'check'?"));
    }
    SECTION("a case file without a command suggests run and check") {
        const Run r = run_coremodal(dir, "case.toml");
        CHECK(r.exit_code == 64);  // EX_USAGE (app/commands.hpp kExitUsage)
        CHECK_THAT(r.err, Catch::Contains("did you mean 'coremodal run case.toml' or 'coremodal check case.toml'?"));
    }
    SECTION("no command at all lists them") {
        const Run r = run_coremodal(dir, "");
        CHECK(r.exit_code == 64);  // EX_USAGE (app/commands.hpp kExitUsage)
        CHECK_THAT(r.err, Catch::Contains("no command given; expected one of run, check"));
    }
}

TEST_CASE("A misspelt option gets the command's nearest option", "[app][cli]") {
    TempDir dir;
    SECTION("run --mehs") {
        const Run r = run_coremodal(dir, "run case.toml --mehs coarse");
        CHECK(r.exit_code == 64);  // EX_USAGE (app/commands.hpp kExitUsage)
        CHECK_THAT(r.err, Catch::Contains("coremodal run: unknown option '--mehs'; did you mean '--mesh'?"));
        CHECK_THAT(r.err, Catch::Contains("--output"));
    }
    SECTION("check --modle=beam, the value attached") {
        const Run r = run_coremodal(dir, "check case.toml --modle=beam");
        CHECK(r.exit_code == 64);  // EX_USAGE (app/commands.hpp kExitUsage)
        CHECK_THAT(r.err, Catch::Contains("coremodal check: unknown option '--modle'; did you mean '--model'?"));
    }
    SECTION("an option far from every option lists them without a guess") {
        const Run r = run_coremodal(dir, "run case.toml --frobnicate");
        CHECK(r.exit_code == 64);  // EX_USAGE (app/commands.hpp kExitUsage)
        CHECK_THAT(r.err, Catch::Contains("unknown option '--frobnicate'; expected one of"));
    }
}

TEST_CASE("Every usage error exits with EX_USAGE (64); --help with 0", "[app][cli]") {
    TempDir dir;
    // A missing case file argument, a value outside its set, a value of the wrong type: CLI11's own
    // messages (its exit codes 106, 105, ... before).
    for (const char* line : {"run", "run case.toml --model beem", "batch cases --jobs many", "study"}) {
        const Run r = run_coremodal(dir, line);
        INFO(line << ": " << r.err);
        CHECK(r.exit_code == 64);
        CHECK_FALSE(r.err.empty());
    }
    for (const char* line : {"--help", "run --help", "campbell --help"}) {
        const Run r = run_coremodal(dir, line);
        INFO(line);
        CHECK(r.exit_code == 0);
    }
}

TEST_CASE("The options --mesh and --no-plots are accepted by every command that writes results", "[app][cli]") {
    TempDir dir;
    dir.write("spin.toml", kClampedTesterCore + "[rotation]\nspeeds = [\"0 rpm\", \"3000 rpm\"]\npoints = 3\n");
    dir.write("resp.toml", kClampedTesterCore + "[damping]\nratio = 0.01\n[excitation]\nunbalance = \"2 kg*mm\"\n"
                           "[response]\nweb_speeds = [\"5 m/s\", \"30 m/s\"]\npoints = 10\n");
    SECTION("campbell, response and run on such cases apply --mesh: an unknown level is refused by name") {
        for (const char* line : {"campbell spin.toml --mesh nonsense -o a", "response resp.toml --mesh nonsense -o b",
                                 "run spin.toml --mesh nonsense -o c", "run resp.toml --mesh nonsense -o d"}) {
            const Run r = run_coremodal(dir, line);
            INFO(line << ": " << r.err);
            CHECK(r.exit_code == 1);
            CHECK_THAT(r.err, Catch::Contains("--mesh nonsense: unknown mesh level; expected one of coarse"));
        }
    }
    SECTION("where it has no use, the option is answered with why, and the command goes on") {
        const struct {
            const char* line;
            const char* note;
        } cases[] = {{"winder missing.toml --mesh coarse", "--mesh is not used by `coremodal winder`"},
                     {"converge missing.toml --mesh fine", "--mesh is not used by `coremodal converge`"},
                     {"fit missing.toml --no-plots", "--no-plots is not used by `coremodal fit`"},
                     {"sensitivity missing.toml --no-plots", "--no-plots is not used by `coremodal sensitivity`"}};
        for (const auto& c : cases) {
            const Run r = run_coremodal(dir, c.line);
            INFO(c.line << ": " << r.err);
            CHECK(r.exit_code == 1);  // the missing file, not the command line
            CHECK_THAT(r.err, Catch::Contains(c.note));
            CHECK_THAT(r.err, Catch::Contains("missing.toml"));
        }
    }
    SECTION("batch passes --no-plots on to every case") {
        dir.write("tiny.toml", kTinyCase);
        const Run r = run_coremodal(dir, "batch tiny.toml --no-plots --jobs 1 -o out");
        INFO(r.out << r.err);
        REQUIRE(r.exit_code == 0);
        CHECK(std::filesystem::exists(dir.path / "out" / "tiny" / "report.md"));
        CHECK_FALSE(std::filesystem::exists(dir.path / "out" / "tiny" / "spectrum.png"));
    }
}

TEST_CASE("coremodal --version names the program and the solver libraries it was built with", "[app][cli]") {
    TempDir dir;
    const Run r = run_coremodal(dir, "--version");
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::StartsWith("coremodal " COREMODAL_VERSION));
    CHECK_THAT(r.out, Catch::Contains("PETSc 3."));
    CHECK_THAT(r.out, Catch::Contains("SLEPc 3."));
    CHECK_THAT(r.out, Catch::Contains("gmsh 4."));
}
