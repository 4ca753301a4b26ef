// `coremodal response` (and `run` on a [response] case) as a user meets it:
// the real binary on a small bowed roll; bad input and an occupied output
// folder refused before any work, nothing written.
#include "support/program_run.hpp"
#include "support/tiny_case.hpp"
#include "support/json_lookup.hpp"  // json_at: read back summary.json

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

bool written(const fs::path& p) { return fs::is_regular_file(p) && fs::file_size(p) > 0; }

// Case 12's core at the beam level (f1 ~ 69 Hz, 23 m/s at Do 106 mm), spinning
// with an unbalance and an oval wall.
const std::string kSmall = kClampedTesterCore + R"([damping]
ratio = 0.01
[excitation]
unbalance = "2 kg*mm"
ovality = "0.3 mm"
)";

}  // namespace

TEST_CASE("coremodal response writes the amplitude table, the peaks, the picture and the report", "[app][response]") {
    TempDir dir("response");
    dir.write("small.toml", kSmall + "[response]\nweb_speeds = [\"5 m/s\", \"30 m/s\"]\npoints = 80\n");
    const Run r = run_coremodal(dir, "response small.toml --output out");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    for (const char* f : {"response.csv", "peaks.csv", "summary.json", "report.md", "response.png"})
        CHECK(written(dir.path / "out" / f));
    const std::string csv = slurp(dir.path / "out" / "response.csv");
    CHECK(csv.rfind("web_speed_m_s,speed_rpm,speed_hz,probe,position_m,amplitude_mm,order_1_mm,order_2_mm\n", 0) == 0);
    const std::string summary = slurp(dir.path / "out" / "summary.json");
    for (const char* effect : {"\"gyroscopic\"", "\"modal_damping\"", "\"unbalance\"", "\"ovality_gravity\"", "\"gravity\""})
        CHECK(summary.find(effect) != std::string::npos);
    CHECK(summary.find("\"bow\"") == std::string::npos);  // not given: not simulated
    CHECK(summary.find("from_amplitude_limit") != std::string::npos);
    // I-5 in the shape of every summary.json: {safe, v_safe_m_s, v_safe_m_min} for 0.7 and 0.8.
    const auto safe = coremodal::json_at(summary, "speeds.safe_web_speed");
    REQUIRE(safe);
    REQUIRE(safe->size() == 2);
    CHECK((*safe)[0]["safe"].get<double>() == 0.7);
    CHECK((*safe)[1]["v_safe_m_s"].get<double>() > (*safe)[0]["v_safe_m_s"].get<double>());
    CHECK((*safe)[0]["v_safe_m_min"].get<double>() == Approx(60 * (*safe)[0]["v_safe_m_s"].get<double>()));
    CHECK(coremodal::json_string(summary, "program") == "coremodal " COREMODAL_VERSION);
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(report.find("## Safe web speed") != std::string::npos);
    CHECK(report.find("## Resonance peaks") != std::string::npos);
    // `run` on the same case does the same.
    const Run run = run_coremodal(dir, "run small.toml --output again --no-plots -q");
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    CHECK(written(dir.path / "again" / "response.csv"));
    CHECK(slurp(dir.path / "again" / "response.csv") == csv);
}

TEST_CASE("coremodal response --model harmonic runs the same scene on its r-z section, into the same files",
          "[app][response][harmonic]") {
    TempDir dir("response_harmonic");
    dir.write("small.toml", kSmall + "[response]\nweb_speeds = [\"5 m/s\", \"30 m/s\"]\npoints = 40\n");
    const Run r = run_coremodal(dir, "response small.toml --model harmonic --output out --no-plots");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    for (const char* f : {"response.csv", "peaks.csv", "summary.json", "report.md"}) CHECK(written(dir.path / "out" / f));
    const std::string summary = slurp(dir.path / "out" / "summary.json");
    CHECK(summary.find("\"level\": \"harmonic\"") != std::string::npos);
    CHECK(summary.find("\"reference\": \"direct solve\"") != std::string::npos);
    CHECK(slurp(dir.path / "out" / "report.md").find("Harmonic level (wave number n = 1)") != std::string::npos);
    CHECK(slurp(dir.path / "out" / "response.csv").rfind("web_speed_m_s,speed_rpm,speed_hz,probe,position_m,amplitude_mm,order_1_mm,order_2_mm\n", 0) == 0);
}

TEST_CASE("coremodal response refuses what it cannot do before any work, and writes nothing", "[app][response]") {
    TempDir dir("response_refused");
    dir.write("still.toml", kSmall.substr(0, kSmall.find("[damping]")));
    const Run still = run_coremodal(dir, "response still.toml --output out");
    CHECK(still.exit_code == 1);
    CHECK(still.err.find("still.toml: no [response] table") != std::string::npos);
    dir.write("bad.toml", kSmall + "[response]\nweb_speeds = [\"20 m/s\", \"5 m/s\"]\n");
    const Run bad = run_coremodal(dir, "response bad.toml --output out");
    CHECK(bad.exit_code == 1);
    CHECK(bad.err.find("bad.toml:20:25: [response] web_speeds") != std::string::npos);
    // The solid and harmonic levels spin bodies of revolution only: a user mesh is refused before it is read.
    dir.write("user.msh", "");
    dir.write("solid.toml", kSmall + "[response]\nweb_speeds = [\"5 m/s\", \"20 m/s\"]\n[mesh]\nfile = \"user.msh\"\n");
    const Run solid = run_coremodal(dir, "response solid.toml --model solid --output out");
    CHECK(solid.exit_code == 1);
    CHECK(solid.err.find("solid.toml: [response] at the solid level: a [mesh] file") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out"));
    // An existing folder that is not a coremodal result is never touched.
    fs::create_directories(dir.path / "mine");
    dir.write("mine/notes.txt", "mine");
    const Run occupied = run_coremodal(dir, "response solid.toml --output mine --no-plots");
    CHECK(occupied.exit_code == 1);
    CHECK(slurp(dir.path / "mine" / "notes.txt") == "mine");
    CHECK(!fs::exists(dir.path / "mine" / "response.csv"));
}
