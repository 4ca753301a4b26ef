// A mistyped command line, as a new user types it: the message names what
// was typed, suggests the nearest valid word and lists the valid ones
// (issue 11, defect 5); `--version` says which build this is.
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal::testing;

TEST_CASE("An unknown command is named, with the commands that exist", "[app][cli]") {
    TempDir dir;
    SECTION("a word that is no command") {
        const Run r = run_coremodal(dir, "frobnicate case.toml");
        CHECK(r.exit_code != 0);
        CHECK_THAT(r.err, Catch::Contains("unknown command 'frobnicate'"));
        for (const char* command : {"run", "check", "beam", "batch", "converge", "study", "calibrate"})
            CHECK_THAT(r.err, Catch::Contains(command));
        // Before: CLI11's "A subcommand is required", which names nothing.
        CHECK_THAT(r.err, !Catch::Contains("A subcommand is required"));
    }
    SECTION("a misspelt command gets the nearest one") {
        const Run r = run_coremodal(dir, "chekc case.toml");
        CHECK(r.exit_code != 0);
        CHECK_THAT(r.err, Catch::Contains("unknown command 'chekc'; did you mean 'check'?"));
    }
    SECTION("a case file without a command suggests run and check") {
        const Run r = run_coremodal(dir, "case.toml");
        CHECK(r.exit_code != 0);
        CHECK_THAT(r.err, Catch::Contains("did you mean 'coremodal run case.toml' or 'coremodal check case.toml'?"));
    }
    SECTION("no command at all lists them") {
        const Run r = run_coremodal(dir, "");
        CHECK(r.exit_code != 0);
        CHECK_THAT(r.err, Catch::Contains("no command given; expected one of run, check"));
    }
}

TEST_CASE("A misspelt option gets the command's nearest option", "[app][cli]") {
    TempDir dir;
    SECTION("run --mehs") {
        const Run r = run_coremodal(dir, "run case.toml --mehs coarse");
        CHECK(r.exit_code != 0);
        CHECK_THAT(r.err, Catch::Contains("coremodal run: unknown option '--mehs'; did you mean '--mesh'?"));
        CHECK_THAT(r.err, Catch::Contains("--output"));
    }
    SECTION("check --modle=beam, the value attached") {
        const Run r = run_coremodal(dir, "check case.toml --modle=beam");
        CHECK(r.exit_code != 0);
        CHECK_THAT(r.err, Catch::Contains("coremodal check: unknown option '--modle'; did you mean '--model'?"));
    }
    SECTION("an option far from every option lists them without a guess") {
        const Run r = run_coremodal(dir, "run case.toml --frobnicate");
        CHECK(r.exit_code != 0);
        CHECK_THAT(r.err, Catch::Contains("unknown option '--frobnicate'; expected one of"));
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
