// `coremodal durability` as a user runs it: the shipped example's steps,
// files and picture; bad data and bad options refused with their place and
// nothing written.
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

bool written(const fs::path& p) { return fs::is_regular_file(p) && fs::file_size(p) > 0; }

const std::string kExample = COREMODAL_SOURCE_DIR "/cases/18-core-durability-76x15.csv";

}  // namespace

TEST_CASE("coremodal durability names every step and writes its tables, picture and report",
          "[app][durability]") {
    TempDir dir("durability");
    const Run r = run_coremodal(dir, "durability " + kExample + " --output out -p 1e-5 -p 1e-3");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    for (const char* step : {"durability: 1. data: 40 points", "2. power-law fit", "3. residuals in log10 y",
                             "4. mean at confidence C = 99 %", "5. upper standard deviation",
                             "6. lambda from the failure probability ({27}): P = 1e-05: -4.265; P = 0.001: -3.090",
                             "7. reduced curves", "8. allowed max_roll_weight at 5000 cycles", "9. results: out/report.md"})
        CHECK(r.out.find(step) != std::string::npos);
    for (const char* f : {"points.csv", "curves.csv", "allowed_weights.csv", "summary.json", "report.md",
                          "durability.png"})
        CHECK(written(dir.path / "out" / f));
    const std::string table = slurp(dir.path / "out" / "allowed_weights.csv");
    CHECK(table.rfind("cycles,P_1e-05_kN,P_0.001_kN\n0.5,", 0) == 0);
    CHECK(table.find("\n5000,") != std::string::npos);
    CHECK(slurp(dir.path / "out" / "summary.json").find("\"chuck_type\": \"non-expanding\"") != std::string::npos);
}

TEST_CASE("coremodal durability refuses bad data and options and writes nothing", "[app][durability]") {
    TempDir dir("durability_bad");
    dir.write("bad.csv", "# chuck_length = 100 mm\n# chuck_type = expanding\ncycles,w [kN]\n0.5,30\n0.2,25\n9,20\n");
    Run r = run_coremodal(dir, "durability bad.csv --output out --no-plots");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("coremodal: error: bad.csv:5:1: cycles = 0.2 is below 0.5") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out"));

    r = run_coremodal(dir, "durability " + kExample + " --output out --no-plots -p 0.7");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("--probability 0.7 is outside (0, 0.5]") != std::string::npos);
    r = run_coremodal(dir, "durability " + kExample + " --output out --no-plots -p 0");
    CHECK(r.err.find("--probability 0 is outside (0, 0.5]") != std::string::npos);
    r = run_coremodal(dir, "durability " + kExample + " --output out --no-plots --confidence 1");
    CHECK(r.err.find("--confidence 1 is outside [0.5, 1)") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out"));

    // The user's own folder is never written over.
    fs::create_directories(dir.path / "mine");
    dir.write("mine/notes.txt", "keep");
    r = run_coremodal(dir, "durability " + kExample + " --output mine --no-plots");
    CHECK(r.exit_code == 1);
    CHECK(slurp(dir.path / "mine" / "notes.txt") == "keep");
}

TEST_CASE("coremodal select writes the chart, the table per stand and the reels' verdicts", "[app][select]") {
    TempDir dir("select");
    const Run r = run_coremodal(dir, "select " COREMODAL_SOURCE_DIR "/cases/18-core-selection.toml --output out");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("select: default [selection.stand rotogravure] li = 100 mm (assumed") != std::string::npos);
    CHECK(r.out.find("select: stand news: 110 mm chucks (k = 0.85), two-drum winder, 15 m/s") != std::string::npos);
    CHECK(r.out.find("select: assumed: width limit: the `coremodal limits` verdict at the beam level") !=
          std::string::npos);
    // The width limit is the limits verdict's (I-5 governs case 18 everywhere; docs/how-to/durability.md).
    CHECK(r.out.find("core A: max roll 1346 kg (13.2 kN), width for the speed 2.145 m (I-5 x0.7; I-7 alone 2.145 m)") !=
          std::string::npos);
    CHECK(r.out.find("select: reel 1 (news, 1.6 m x 1000 mm, 15 m/s): passes A, B; lightest A; cheapest A") !=
          std::string::npos);
    for (const char* f : {"selection.csv", "reels.csv", "summary.json", "report.md", "selection_chart.png"})
        CHECK(written(dir.path / "out" / f));
    const std::string table = slurp(dir.path / "out" / "selection.csv");
    CHECK(table.find("\nrotogravure,C,") != std::string::npos);
    CHECK(table.find("\nnews,C,") == std::string::npos);  // the news stand's chucks take A and B only
}

TEST_CASE("coremodal select refuses a bad file with its place and writes nothing", "[app][select]") {
    TempDir dir("select_bad");
    dir.write("bad.toml", "[selection]\npaper_density = \"750 kg/m^3\"\nrest_paper_modulus = \"5 GPa\"\n"
                          "rest_paper_density = 1350\n[[selection.core]]\nname = \"A\"\ninner_diameter = \"76 mm\"\n"
                          "outer_diameter = \"70 mm\"\n");
    const Run r = run_coremodal(dir, "select bad.toml --output out --no-plots");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("bad.toml:8:18: [selection.core A] outer_diameter = 70 mm must be larger than inner_diameter = "
                     "76 mm") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out"));
}

TEST_CASE("A selection file: check validates it, run names the command that runs it", "[app][select][check]") {
    TempDir dir;
    const std::string file = COREMODAL_SOURCE_DIR "/cases/18-core-selection.toml";
    const Run checked = run_coremodal(dir, "check '" + file + "'");
    CHECK(checked.exit_code == 0);
    CHECK(checked.out.find("valid core-selection file \"18-core-selection\": 3 core grade(s), 2 stand(s), 4 reel(s); "
                           "run it with `coremodal select`") != std::string::npos);
    const Run run = run_coremodal(dir, "run '" + file + "'");
    CHECK(run.exit_code == 1);
    CHECK(run.err.find("[selection] is a core-selection file, not a roll's case file; run it with `coremodal select")
          != std::string::npos);
    CHECK(fs::is_empty(dir.path));  // nothing written
}
