// `coremodal study` and `coremodal calibrate` as a user meets them: the real
// binary on small case files in a temporary folder; then `coremodal beam
// --calibration` on what calibrate wrote.
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

bool written(const fs::path& p) { return fs::is_regular_file(p) && fs::file_size(p) > 0; }

// A clamped steel tube, 792 DOFs a point.
const std::string kTinyStudy = R"(name = "tiny"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "0.5 m"
material = { E = "210 GPa", nu = 0.3, density = "7850 kg/m^3" }

[supports]
type = "clamped"

[supports.left]
length = "40 mm"

[mesh]
around = 8
along = 8
through_wall = 1

[study]
modes = 6
web_speed = "14 m/s"
parameters = [{ key = "core.length", values = ["0.5 m", "0.6 m", "0.07 m"] }]
)";

const std::string kTinyStand = R"(name = "stand"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2 m"

[rest_paper]
thickness = "10 mm"

[supports]
type = "clamped"

[supports.left]
length = "70 mm"

[mesh]
through_wall = 1
through_rest_paper = 1
around = 8
along = 16

[calibration]
modes = 4
holdout_every = 3
parameters = [
  { key = "core.length", values = ["1.2 m", "1.7 m", "2.2 m"] },
  { key = "rest_paper.thickness", values = ["5 mm", "15 mm", "30 mm"] },
]
)";

}  // namespace

TEST_CASE("study and calibrate explain themselves with --help", "[app][study][cli]") {
    TempDir dir;
    for (const char* command : {"study", "calibrate"}) {
        const Run r = run_coremodal(dir, std::string(command) + " --help");
        INFO(command);
        CHECK(r.exit_code == 0);
        CHECK(r.out.find("--output") != std::string::npos);
        CHECK(r.out.find("--mesh") != std::string::npos);
        CHECK(r.out.find(std::string(command) == "study" ? "[study]" : "[calibration]") != std::string::npos);
    }
}

TEST_CASE("A study writes its whole folder; a refused point is reported and the others still run",
          "[app][study][cli]") {
    TempDir dir;
    dir.write("tiny.toml", kTinyStudy);
    const Run r = run_coremodal(dir, "study tiny.toml -o out");
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 1);  // one point failed
    CHECK(r.out.find("[1/3] core.length = 0.5 m: f1 ") != std::string::npos);
    CHECK(r.out.find("refused: point 3 (core.length = 0.07 m)") != std::string::npos);
    CHECK(r.err.find("1 point(s) failed") != std::string::npos);
    for (const char* file : {"study.csv", "study.json", "report.md", "modes_vs_core_length.png",
                             "f1_vs_core_length.png", "k_vs_core_length.png"}) {
        INFO(file);
        CHECK(written(dir.path / "out" / file));
    }
    CHECK_FALSE(fs::exists(dir.path / "out" / "plot.log"));
    const std::string csv = slurp(dir.path / "out" / "study.csv");
    CHECK(csv.find("\n3,0.07,failed,") != std::string::npos);
    CHECK(csv.find("\n2,0.6,ok,1,") != std::string::npos);
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(report.find("## Failed points") != std::string::npos);
    CHECK(report.find("![f1_vs_core_length.png](f1_vs_core_length.png)") != std::string::npos);
}

// The value in column `name` of row `row` (1-based data rows) of a CSV text
// without quoted fields.
static std::string csv_cell(const std::string& csv, const std::string& name, int row) {
    std::istringstream in(csv);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::istringstream fields(line);
        for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
        rows.push_back(cells);
    }
    const auto& header = rows.at(0);
    const auto column = std::find(header.begin(), header.end(), name) - header.begin();
    return rows.at(row).at(column);
}

TEST_CASE("study --model runs every point at that level, in worker processes too", "[app][study][cli]") {
    TempDir dir;
    dir.write("tiny.toml", kTinyStudy);
    const Run study = run_coremodal(dir, "study tiny.toml --model beam --jobs 2 --no-plots -q -o out");
    INFO("stderr: " << study.err);
    CHECK(study.exit_code == 1);  // the 0.07 m point is still refused
    const Run run = run_coremodal(dir, "run tiny.toml --model beam --no-plots -q -o run");
    REQUIRE(run.exit_code == 0);
    const std::string summary = slurp(dir.path / "run" / "summary.json");
    const std::string key = "\"fe_first_bending_hz\": ";
    const size_t at = summary.find(key);
    REQUIRE(at != std::string::npos);
    const double f1_run = std::stod(summary.substr(at + key.size()));
    // The beam level's f1 of the 0.5 m point, not the solid's (which differs by percent).
    const double f1_study = std::stod(csv_cell(slurp(dir.path / "out" / "study.csv"), "f1_hz", 1));
    CHECK(f1_study == Approx(f1_run).epsilon(1e-9));
    CHECK(run_coremodal(dir, "study --help").out.find("--model") != std::string::npos);
}

TEST_CASE("A study with a bad key stops before running anything, naming file, line and key", "[app][study][cli]") {
    TempDir dir;
    std::string text = kTinyStudy;
    text.replace(text.find("core.length\", values"), 11, "core.lenght");
    dir.write("bad.toml", text);
    const Run r = run_coremodal(dir, "study bad.toml -o out");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("bad.toml:23:") != std::string::npos);
    CHECK(r.err.find("no key 'lenght' in [core]; did you mean 'length'?") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("calibrate writes a calibration that `coremodal beam --calibration` applies", "[app][calibration][cli]") {
    TempDir dir;
    dir.write("stand.toml", kTinyStand);
    const Run r = run_coremodal(dir, "calibrate stand.toml -o cal --no-plots -q");
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("passed") != std::string::npos);
    for (const char* file : {"calibration.toml", "calibration.csv", "study.csv", "study.json", "report.md"}) {
        INFO(file);
        CHECK(written(dir.path / "cal" / file));
    }
    const std::string report = slurp(dir.path / "cal" / "report.md");
    CHECK(report.find("**PASSED**") != std::string::npos);

    const Run beam = run_coremodal(dir, "beam stand.toml --calibration cal/calibration.toml --json");
    INFO("beam stdout: " << beam.out << "\nstderr: " << beam.err);
    REQUIRE(beam.exit_code == 0);
    CHECK(beam.out.find("\"k_source\"") != std::string::npos);
    CHECK(beam.out.find("\"g3\"") != std::string::npos);
    CHECK(beam.out.find("\"k\": 1.0") == std::string::npos);  // not the default k

    const Run both = run_coremodal(dir, "beam stand.toml --calibration cal/calibration.toml --k 0.8");
    CHECK(both.exit_code == 1);
    CHECK(both.err.find("--k and --calibration both give the chuck factor") != std::string::npos);

    dir.write("not-a-calibration.toml", "x = 1\n");
    const Run bad = run_coremodal(dir, "beam stand.toml --calibration not-a-calibration.toml");
    CHECK(bad.exit_code == 1);
    CHECK(bad.err.find("not-a-calibration.toml") != std::string::npos);
}
