// report.md of `coremodal run`: the mode table, the beam comparison, the
// chuck factor and the safe web speed as a person reads them, with the same
// numbers as summary.json, and the pictures it links drawn beside it. A run
// without python still succeeds and says why there are no pictures.
#include "beam/formulas.hpp"
#include "common/format.hpp"
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace coremodal;
using namespace coremodal::testing;

namespace {

// A clamped steel tube 76 x 15 mm, 0.5 m, 3,168 DOFs: a second or two to
// solve. 16 around, so that the run has nothing to warn about: at 8 around
// its first ovalling pair was 14 % above the harmonic level's (exact around)
// and the run said so; at 16 it is 1.2 % above (docs/validation/accuracy-by-level.md,
// "Does the mesh resolve the band"). Seven modes end on that complete pair.
const std::string kClampedTube = R"(name = "clamped-tube"
description = "A short clamped steel tube"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "0.5 m"
material = { E = "210 GPa", nu = 0.3, density = "7850 kg/m^3" }

[supports]
type = "clamped"

[supports.left]
length = "40 mm"

[analysis]
modes = 7

[mesh]
around = 16
along = 8
through_wall = 1
)";

// Every value of "key" : number in a JSON text, in order.
std::vector<double> json_numbers(const std::string& json, const std::string& key) {
    std::vector<double> values;
    const std::regex pattern("\"" + key + "\": (-?[0-9.eE+-]+)");
    for (auto it = std::sregex_iterator(json.begin(), json.end(), pattern); it != std::sregex_iterator(); ++it)
        values.push_back(std::stod((*it)[1]));
    return values;
}

// The files of the markdown's ![...](file) links.
std::vector<std::string> linked_pictures(const std::string& markdown) {
    std::vector<std::string> files;
    const std::regex link(R"(!\[[^\]]*\]\(([^)]+)\))");
    for (auto it = std::sregex_iterator(markdown.begin(), markdown.end(), link); it != std::sregex_iterator(); ++it)
        files.push_back((*it)[1]);
    return files;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("A run writes report.md with the numbers of summary.json and the pictures it links", "[app][cli][report]") {
    // Blocks, not SECTIONs: Catch2 reruns a test case once per section, and
    // the run is the cost.
    TempDir dir("report");
    dir.write("tube.toml", kClampedTube);
    const Run r = run_coremodal(dir, "run tube.toml -o out -q");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    const std::string report = slurp(dir.path / "out" / "report.md");
    const std::string summary = slurp(dir.path / "out" / "summary.json");
    REQUIRE(!report.empty());
    CHECK(contains(report, "# clamped-tube\n\nA short clamped steel tube"));
    CHECK(contains(report, "| supports | clamped: left z = 0…0.04 m; right z = 0.46…0.5 m |"));

    {
        INFO("The mode table has a row per mode with the frequency of summary.json");
        const std::vector<double> f = json_numbers(summary, "frequency_hz");
        REQUIRE(f.size() == 7);
        for (size_t i = 0; i < f.size(); ++i) {
            INFO("mode " << i + 1);
            CHECK(contains(report, "\n| " + std::to_string(i + 1) + " | " + formatted("%.4f", f[i]) + " | "));
        }
        CHECK(contains(report, "**complete**"));
    }
    {
        INFO("The beam comparison sets Euler-Bernoulli and Timoshenko beside the FE f1");
        const double eb = json_numbers(summary, "euler_bernoulli_hz").at(0);
        const double timo = json_numbers(summary, "timoshenko_hz").at(0);
        const double fe = json_numbers(summary, "fe_first_bending_hz").at(0);
        CHECK(contains(report, "| Euler–Bernoulli (I-7, k = 1) | " + formatted("%.4f", eb) + " | " +
                                   formatted("%.4f", fe / eb) + " |"));
        CHECK(contains(report, "| Timoshenko (beam FE) | " + formatted("%.4f", timo) + " | " +
                                   formatted("%.4f", fe / timo) + " |"));
    }
    {
        INFO("The safe web speed is safe pi Dp f1 with Dp the core's outer diameter");
        const double f1 = json_numbers(summary, "fe_first_bending_hz").at(0);
        // No rest paper: Dp = 76 + 2 x 15 = 106 mm; v = 0.7 x pi x 0.106 m x f1
        // = 0.23311 m x f1 (f1 ~ 1.5 kHz for this short steel tube: ~350 m/s);
        // with safe = 0.8, 0.26641 m x f1.
        const double v07 = 0.7 * M_PI * 0.106 * f1, v08 = 0.8 * M_PI * 0.106 * f1;
        CHECK(v07 == Approx(safe_web_speed(f1, 0.106, 0.7)).epsilon(1e-14));
        CHECK(v08 == Approx(safe_web_speed(f1, 0.106, 0.8)).epsilon(1e-14));
        CHECK(contains(report, "| 0.7 | " + significant(v07) + " m/s"));
        CHECK(contains(report, "| 0.8 | " + significant(v08) + " m/s"));
        CHECK(contains(report, "König's critical speed (K-1"));
        // summary.json holds the same speeds (it had none before: report.md only).
        const std::vector<double> v_safe = json_numbers(summary, "v_safe_m_s");
        REQUIRE(v_safe.size() == 2);
        CHECK(v_safe[0] == Approx(v07).epsilon(1e-12));
        CHECK(v_safe[1] == Approx(v08).epsilon(1e-12));
        CHECK(json_numbers(summary, "dp_m").at(0) == Approx(0.106).epsilon(1e-12));
        const double v_krit = json_numbers(summary, "v_krit_m_s").at(0);
        CHECK(contains(report, "v_krit = " + significant(v_krit) + " m/s"));
    }
    {
        INFO("Every linked picture exists: the spectrum and one of each mode type");
        const auto pictures = linked_pictures(report);
        CHECK(pictures.size() >= 3);  // spectrum, bending, torsion (and more)
        CHECK(std::find(pictures.begin(), pictures.end(), "spectrum.png") != pictures.end());
        for (const auto& p : pictures) {
            INFO(p);
            CHECK(fs::is_regular_file(dir.path / "out" / p));
        }
        CHECK_FALSE(fs::exists(dir.path / "out" / "plot.log"));
    }
}

TEST_CASE("Without python the run still succeeds and report.md says why there are no pictures",
          "[app][cli][report]") {
    TempDir dir("report");
    dir.write("tube.toml", kClampedTube);
    const Run r = run_coremodal(dir, "run tube.toml -o out -q", "COREMODAL_PYTHON=/nonexistent ");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(contains(r.err, "coremodal: warning: no pictures in report.md"));
    CHECK(contains(r.err, "/nonexistent"));
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(contains(report, "No pictures: /nonexistent -m coremodal run-plot could not start"));
    CHECK(linked_pictures(report).empty());
    CHECK(fs::is_regular_file(dir.path / "out" / "summary.json"));
    CHECK_FALSE(fs::exists(dir.path / "out" / "plot.log"));
}

TEST_CASE("A chuck scene's report has the chuck factor block with the k of summary.json", "[app][cli][report]") {
    TempDir dir("report");
    const std::string chuck_case = std::string(COREMODAL_SOURCE_DIR) + "/cases/08-news-chucks-76x15-2200.toml";
    const Run r = run_coremodal(dir, "run '" + chuck_case + "' -o out -q --mesh coarse --no-plots");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());  // --no-plots: no warning
    const std::string report = slurp(dir.path / "out" / "report.md");
    const std::string summary = slurp(dir.path / "out" / "summary.json");
    CHECK(contains(report, "## Chuck factor"));
    CHECK(contains(report, "| Li left / right | 70 mm / 70 mm |"));
    const double k = json_numbers(summary, "chuck_factor").at(0);
    CHECK(contains(report, "| **k = f1/f2 (FE)** | **" + formatted("%.4f", k) + "** |"));
    CHECK(contains(report, "| free span L | " + significant(json_numbers(summary, "free_span_m").at(0)) + " m |"));
    CHECK(contains(report, "rigid bearings"));
    // Case 08 has no rest paper: the speeds use the core's OD, 106 mm.
    const double f1 = json_numbers(summary, "fe_first_bending_hz").at(0);
    CHECK(contains(report, "| 0.7 | " + significant(safe_web_speed(f1, 0.106, 0.7)) + " m/s"));
    CHECK(contains(report, "between the chucks' inserted ends"));
    CHECK(contains(summary, "\"span\": \"between the chucks' inserted ends\""));
    CHECK(json_numbers(summary, "v_safe_m_s").at(0) == Approx(safe_web_speed(f1, 0.106, 0.7)).epsilon(1e-12));
    CHECK(contains(report, "No pictures: switched off (--no-plots)"));
    CHECK(linked_pictures(report).empty());
}

TEST_CASE("A beam-level run writes report.md too, without pictures", "[app][cli][report]") {
    TempDir dir("report");
    const std::string beam_case =
        std::string(COREMODAL_SOURCE_DIR) + "/cases/05-beam-level-rest-roll-150x15.8-4320.toml";
    const Run r = run_coremodal(dir, "run '" + beam_case + "' -o out -q");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(contains(report, "## Modes"));
    CHECK(contains(report, "the beam model level has no mesh to draw"));
}
