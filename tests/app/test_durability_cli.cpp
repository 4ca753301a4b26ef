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

const std::string kExample = COREMODAL_SOURCE_DIR "/cases/16-core-durability-76x15.csv";

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
