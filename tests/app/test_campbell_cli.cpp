// `coremodal campbell` (and `run` on a [rotation] case) as a user meets it:
// the real binary on the rotation tester's case; bad input and an occupied
// output folder refused before any work, nothing written.
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

const std::string kTester = std::string(COREMODAL_SOURCE_DIR) + "/cases/12-rotation-tester-76x15.toml";

const std::string kSmall = kClampedTesterCore;

}  // namespace

TEST_CASE("coremodal campbell writes the Campbell table, the critical speeds, the picture and the report",
          "[app][rotation]") {
    TempDir dir("campbell");
    const Run r = run_coremodal(dir, "campbell '" + kTester + "' --output out");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    for (const char* f : {"campbell.csv", "critical_speeds.csv", "summary.json", "report.md", "campbell.png"})
        CHECK(written(dir.path / "out" / f));
    const std::string csv = slurp(dir.path / "out" / "campbell.csv");
    CHECK(csv.rfind("speed_rpm,speed_hz,track,frequency_hz,whirl,label,relative_residual\n", 0) == 0);
    CHECK(csv.find(",FW,") != std::string::npos);
    CHECK(csv.find(",BW,") != std::string::npos);
    const std::string summary = slurp(dir.path / "out" / "summary.json");
    CHECK(summary.find("\"gyroscopic\"") != std::string::npos);
    CHECK(summary.find("\"centrifugal_stiffening\"") == std::string::npos);  // not included at the beam level
    // I-5 in the shape of every summary.json: {safe, v_safe_m_s, v_safe_m_min} for 0.7 and 0.8.
    const auto safe = coremodal::json_at(summary, "speeds.safe_web_speed");
    REQUIRE(safe);
    REQUIRE(safe->size() == 2);
    CHECK((*safe)[0]["safe"].get<double>() == 0.7);
    CHECK((*safe)[1]["v_safe_m_s"].get<double>() > (*safe)[0]["v_safe_m_s"].get<double>());
    CHECK((*safe)[0]["v_safe_m_min"].get<double>() == Approx(60 * (*safe)[0]["v_safe_m_s"].get<double>()));
    CHECK(coremodal::json_string(summary, "program") == "coremodal " COREMODAL_VERSION);
    CHECK(summary.find("first_order_1_critical") != std::string::npos);
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(report.find("## Critical speeds") != std::string::npos);
    CHECK(report.find("I-5 safe web speed") != std::string::npos);
    // The tester's operating range 0-4000 rpm (operating_speeds): the order-2 crossings of the first bending pair
    // (69.1 Hz at rest, so near 30 x 69.1 = 2073 rpm) lie inside it, the order-1 ones (near 4150 rpm) above it.
    const auto range = coremodal::json_at(summary, "rotation.operating_speeds_rpm");
    REQUIRE(range);
    CHECK((*range)[0].get<double>() == Approx(0.0).margin(1e-9));
    CHECK((*range)[1].get<double>() == Approx(4000.0));
    const auto critical = coremodal::json_at(summary, "critical_speeds");
    REQUIRE(critical);
    int inside = 0;
    for (const auto& c : *critical) {
        const double rpm = c["speed_rpm"].get<double>();
        CHECK(c["inside_operating_range"].get<bool>() == (rpm <= 4000.0));
        if (c["inside_operating_range"].get<bool>()) {
            ++inside;
            CHECK(c["order"].get<int>() == 2);
            CHECK(rpm == Approx(2073.0).epsilon(0.01));
        }
    }
    CHECK(inside == 2);
    CHECK(r.out.find("critical speed 2071.6 rpm inside the operating range 0 rpm to 4000 rpm") != std::string::npos);
    CHECK(report.find("inside the operating range") != std::string::npos);
}

TEST_CASE("coremodal run on a case with one speed reports the modes at that speed", "[app][rotation]") {
    TempDir dir("campbell_run");
    dir.write("one.toml", kSmall + "[rotation]\nspeed = \"3000 rpm\"\n");
    const Run r = run_coremodal(dir, "run one.toml --output out --no-plots");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string csv = slurp(dir.path / "out" / "campbell.csv");
    CHECK(csv.find("\n3000,50,") != std::string::npos);
    CHECK(csv.find("\n0,0,") == std::string::npos);  // only the speed asked for
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(report.find("## Modes at 3000 rpm") != std::string::npos);
    CHECK(report.find(" Hz | FW | bending n=1 m=0 |") != std::string::npos);
}

TEST_CASE("The summary lists centrifugal stiffening exactly when the harmonic level simulated it", "[app][rotation]") {
    TempDir dir("campbell_effects");
    dir.write("on.toml", kSmall + "[rotation]\nspeed = \"3000 rpm\"\n");
    dir.write("off.toml", kSmall + "[rotation]\nspeed = \"3000 rpm\"\ncentrifugal_stiffening = false\n");
    for (const char* name : {"on", "off"}) {
        const Run r = run_coremodal(dir, std::string("run ") + name + ".toml --model harmonic --output " + name +
                                             " --no-plots");
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        const std::string summary = slurp(dir.path / name / "summary.json");
        const bool on = std::string(name) == "on";
        CHECK((summary.find("\"centrifugal_stiffening\"") != std::string::npos) == on);
        CHECK((summary.find("centrifugal stiffening: the steady stress of the spinning section") != std::string::npos) ==
              on);
        CHECK((summary.find("[rotation] centrifugal_stiffening = false") != std::string::npos) == !on);
        CHECK(summary.find("\"gyroscopic\"") != std::string::npos);
    }
}

TEST_CASE("coremodal campbell refuses what it cannot do before any work, and writes nothing", "[app][rotation]") {
    TempDir dir("campbell_bad");
    dir.write("still.toml", kSmall);
    const Run still = run_coremodal(dir, "campbell still.toml --output out");
    CHECK(still.exit_code == 1);
    CHECK(still.err.find("still.toml: no [rotation] table") != std::string::npos);
    // A chuck not expanded (case 09): gravity and a one-sided contact stay
    // put while the roll turns, constant in neither frame.
    dir.write("loose.toml", slurp(std::string(COREMODAL_SOURCE_DIR) + "/cases/09-news-chucks-not-expanded-76x15-2200.toml") +
                                "\n[rotation]\nspeed = \"10 Hz\"\n");
    const Run loose = run_coremodal(dir, "campbell loose.toml --output out");
    CHECK(loose.exit_code == 1);
    CHECK(loose.err.find("[rotation] at the solid level: the left chuck is not expanded") != std::string::npos);
    CHECK(loose.err.find("time-periodic") != std::string::npos);
    dir.write("bad.toml", kSmall + "[rotation]\nspeeds = [\"10 Hz\", \"5 Hz\"]\n");
    const Run bad = run_coremodal(dir, "campbell bad.toml --output out");
    CHECK(bad.exit_code == 1);
    CHECK(bad.err.find("bad.toml:15:20:") != std::string::npos);
    // [damping] at a level whose operator sets do not carry it: the level that does.
    dir.write("damped.toml", kSmall + "[rotation]\nspeed = \"10 Hz\"\n[damping]\nloss_factor = 0.02\n");
    const Run damped = run_coremodal(dir, "campbell damped.toml --output out");
    CHECK(damped.exit_code == 1);
    CHECK(damped.err.find("[damping] in a Campbell sweep at model = \"beam\"") != std::string::npos);
    CHECK(damped.err.find("expected model = \"harmonic\"") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out"));
    // An existing folder that is not a coremodal result is never touched.
    fs::create_directories(dir.path / "mine");
    dir.write("mine/notes.txt", "mine");
    dir.write("ok.toml", kSmall + "[rotation]\nspeed = \"10 Hz\"\n");
    const Run occupied = run_coremodal(dir, "campbell ok.toml --output mine --no-plots");
    CHECK(occupied.exit_code == 1);
    CHECK(slurp(dir.path / "mine" / "notes.txt") == "mine");
    CHECK(!fs::exists(dir.path / "mine" / "campbell.csv"));
}
