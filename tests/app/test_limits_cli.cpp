// `coremodal limits` as a user meets it: the real binary on a small clamped
// rest roll at the beam level; the console ends with the verdict line (also
// under -q); bad input refused before any work, naming the key, nothing
// written.
#include "support/program_run.hpp"
#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

bool written(const fs::path& p) { return fs::is_regular_file(p) && fs::file_size(p) > 0; }

// Case 12's core with 10 mm of rest paper (Dp 126 mm), clamped, beam level.
const std::string kRoll = kClampedTesterCore + R"([rest_paper]
thickness = "10 mm"
material = "rest_paper"
)";

std::string last_line(const std::string& text) {
    const size_t end = text.find_last_not_of('\n');
    const size_t start = text.rfind('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1,
                       end - (start == std::string::npos ? 0 : start + 1) + 1);
}

}  // namespace

TEST_CASE(
    "coremodal limits writes the verdict table, the picture and the "
    "report, and ends with the verdict",
    "[app][limits]") {
    TempDir dir("limits");
    dir.write("roll.toml", kRoll + "[limits]\npoints = 3\nweb_speed = \"15 m/s\"\nband = false\n");
    const Run r = run_coremodal(dir, "limits roll.toml --output out");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    for (const char* f : {"limits.csv", "amplitude.csv", "summary.json", "report.md", "limits.png"})
        CHECK(written(dir.path / "out" / f));
    CHECK(last_line(r.out).rfind("safe up to ", 0) == 0);
    CHECK(last_line(r.out).find("governed by") != std::string::npos);
    const std::string summary = slurp(dir.path / "out" / "summary.json");
    CHECK(summary.find("\"command\": \"limits\"") != std::string::npos);  // the one scheme (output/summary_json.hpp)
    CHECK(summary.find("\"roll_change_diameter_mm\"") != std::string::npos);
    CHECK(summary.find("\"web_speed_m_s\": 15.0") != std::string::npos);
    CHECK(slurp(dir.path / "out" / "report.md").rfind("# How fast may small run: safe up to ", 0) == 0);
    CHECK(slurp(dir.path / "out" / "limits.csv").rfind("diameter_mm,added,f1_hz,chuck_factor,i5_0.7_m_s,", 0) == 0);
    // Progress: one line per diameter as it is solved, before the table.
    for (const char* k : {"(1/3): f1 ", "(2/3): f1 ", "(3/3): f1 "}) CHECK(r.out.find(k) != std::string::npos);
    CHECK(r.out.find("(3/3): f1 ") < r.out.find("D (mm)"));
    // -q: only where the results are, and the verdict.
    const Run quiet = run_coremodal(dir, "limits roll.toml --output again -q --no-plots --speed 12");
    INFO(quiet.err);
    REQUIRE(quiet.exit_code == 0);
    CHECK(last_line(quiet.out).rfind("safe up to ", 0) == 0);
    CHECK(last_line(quiet.out).find("target 12.00 m/s") != std::string::npos);
    CHECK(quiet.out.find("rest-roll diameters") == std::string::npos);
    CHECK(quiet.out.find("(1/3)") == std::string::npos);
}

TEST_CASE(
    "coremodal limits refuses bad input before any work, naming the key, "
    "and writes nothing",
    "[app][limits]") {
    TempDir dir("limits_refused");
    const auto refused = [&](const std::string& file, const std::string& text, const std::string& options,
                             const std::string& expected) {
        dir.write(file, text);
        const Run r = run_coremodal(dir, "limits " + file + " --output out " + options);
        INFO(r.err);
        CHECK(r.exit_code == 1);
        CHECK(r.err.find(expected) != std::string::npos);
        CHECK_FALSE(fs::exists(dir.path / "out"));
    };
    refused("beyond.toml", kRoll + "[limits]\ndiameters = [\"300 mm\", \"106 mm\"]\n", "",
            "[limits] diameters = [\"300 mm\", \"106 mm\"]: 300 mm is beyond the "
            "case's roll");
    refused("below.toml", kRoll + "[limits]\ndiameters = [\"126 mm\", \"90 mm\"]\n", "",
            "90 mm is below the core; expected at least the core's outer diameter 106 mm");
    refused("slow.toml", kRoll + "[limits]\nweb_speed = \"-3 m/s\"\n", "", "[limits] web_speed");
    refused("speed.toml", kRoll, "--speed -3", "--speed = -3 m/s: the target web speed must be above 0");
    std::string free = kRoll;
    const std::string clamped = "type = \"clamped\"", left = "[supports.left]\nlength = \"70 mm\"\n";
    free.replace(free.find(clamped), clamped.size(), "type = \"free\"");
    free.replace(free.find(left), left.size(), "");
    refused("free.toml", free, "", "[supports] is free-free");
    refused("coupled.toml", kRoll, "--model coupled", "model = \"coupled\" cannot carry");
}

TEST_CASE(
    "coremodal beam says what k = 1 means when neither --k nor "
    "--calibration gives it",
    "[app][limits][beam]") {
    TempDir dir("beam_k");
    dir.write("roll.toml", kRoll);
    const Run assumed = run_coremodal(dir, "beam roll.toml");
    INFO(assumed.err);
    REQUIRE(assumed.exit_code == 0);
    CHECK(assumed.out.find("k = 1 assumed: the core rigidly clamped at Li") != std::string::npos);
    const Run json = run_coremodal(dir, "beam roll.toml --json");
    CHECK(json.out.find("\"k_assumed\"") != std::string::npos);
    const Run given = run_coremodal(dir, "beam roll.toml --k 0.8");
    REQUIRE(given.exit_code == 0);
    CHECK(given.out.find("k = 1 assumed") == std::string::npos);
}

TEST_CASE("coremodal run on a roll in its stand ends with the verdict line, also under -q", "[app][limits]") {
    TempDir dir("limits_run");
    dir.write("roll.toml", kRoll);
    const Run r = run_coremodal(dir, "run roll.toml --output out -q --no-plots");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(last_line(r.out).rfind("verdict at the case's roll (beam level, no band", 0) == 0);
    CHECK(last_line(r.out).find("safe up to ") != std::string::npos);
    CHECK(last_line(r.out).find("governed by") != std::string::npos);
}

TEST_CASE("coremodal limits --fit narrows the band with a measured first resonance; a file that does not name "
          "the case is refused",
          "[app][limits][fit]") {
    TempDir dir("limits_fit");
    dir.write("roll.toml", kRoll + "[limits]\npoints = 2\n");
    // The roll's first resonance as the model has it, measured to +-0.1 Hz:
    // E_z is then known to about +-1 %, narrower than the band's +-15 %.
    const Run plain = run_coremodal(dir, "limits roll.toml --output plain -q --no-plots");
    INFO(plain.err);
    REQUIRE(plain.exit_code == 0);
    const std::string summary = slurp(dir.path / "plain" / "summary.json");
    const size_t at = summary.find("\"f1_hz\": ");
    REQUIRE(at != std::string::npos);
    const double f1 = std::stod(summary.substr(at + 9));
    dir.write("measured.toml", "parameters = [\"core.material.E_z\"]\n[[measurement]]\ncase = \"roll.toml\"\n"
                               "mode = \"bending n=1 m=0\"\nfrequency = \"" + std::to_string(f1) +
                                   " Hz\"\nuncertainty = \"0.1 Hz\"\n");
    const Run fitted = run_coremodal(dir, "limits roll.toml --fit measured.toml --output fitted -q --no-plots");
    INFO(fitted.err);
    REQUIRE(fitted.exit_code == 0);
    CHECK(last_line(fitted.out).rfind("safe up to ", 0) == 0);
    const std::string narrowed = slurp(dir.path / "fitted" / "summary.json");
    CHECK(narrowed.find("fitted: core.material.E_z") != std::string::npos);
    // Not this case: refused before any work, nothing written.
    dir.write("other.toml", kRoll);
    dir.write("elsewhere.toml", "parameters = [\"core.material.E_z\"]\n[[measurement]]\ncase = \"other.toml\"\n"
                                "mode = \"bending n=1 m=0\"\nfrequency = \"40 Hz\"\n");
    const Run refused = run_coremodal(dir, "limits roll.toml --fit elsewhere.toml --output refused -q");
    CHECK(refused.exit_code == 1);
    CHECK(refused.err.find("--fit elsewhere.toml: no [[measurement]] names roll.toml") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "refused"));
}
