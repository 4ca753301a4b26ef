// The Campbell outputs say where each critical speed comes from (the
// sweep, or the exact pencil of co-rotating coordinates) and where the
// sweep stopped and why (docs/theory/rotation-solid.md, "Critical speeds in co-rotating
// coordinates"). A hand-made result: no solve.
#include "output/campbell_report.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace coremodal;

namespace {

std::string read_all(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

CampbellResult pencil_and_sweep() {
    CampbellResult r;
    r.level = ModelChoice::solid;
    r.excitation_orders = {1, 2};
    r.roll_outer_diameter = 0.106;
    r.points = {{0.0, {{1, 50.0, Whirl::none, {}, 1e-12}}}, {40.0, {{1, 50.1, Whirl::forward, {}, 1e-12}}}};
    r.speeds_at_rest.not_given = "a test";
    WhirlCrossing sweep{2, 1, Whirl::backward, {}};
    sweep.speed_hz = sweep.interpolated_speed_hz = 25.0;
    sweep.frequency_hz = 50.0;
    sweep.refined = true;
    WhirlCrossing pencil{1, 0, Whirl::forward, {}};
    pencil.speed_hz = pencil.interpolated_speed_hz = 50.5;
    pencil.frequency_hz = 50.5;
    pencil.source = CrossingSource::pencil;
    r.critical = {sweep, pencil};
    r.sweep_end = "the sweep stopped at 2400 rpm: a test";
    return r;
}

}  // namespace

TEST_CASE("Campbell outputs name each critical speed's source and the sweep's end", "[rotation][campbell][output]") {
    Scene scene;
    scene.name = "test";
    const CampbellResult r = pencil_and_sweep();
    const std::string console = campbell_console_summary(scene, r);
    CHECK(console.find("3030 rpm") != std::string::npos);
    CHECK(console.find("(pencil, exact)") != std::string::npos);
    CHECK(console.find("the sweep stopped at 2400 rpm") != std::string::npos);
    const std::string md = campbell_report_markdown(scene, r, {}, "none asked");
    CHECK(md.find("| pencil (exact) |") != std::string::npos);
    CHECK(md.find("| sweep |") != std::string::npos);
    CHECK(md.find("1 critical speeds from the pencil") != std::string::npos);
    CHECK(md.find("Critical speeds of the sweep: 1 of 1 refined") != std::string::npos);

    const auto dir = std::filesystem::temp_directory_path() / ("campbell_report_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    write_campbell_tables(dir, scene, RotationSpec{}, r);
    const std::string csv = read_all(dir / "critical_speeds.csv");
    CHECK(csv.find("interpolated_speed_rpm,source\n") != std::string::npos);
    CHECK(csv.find(",sweep\n") != std::string::npos);
    CHECK(csv.find(",pencil\n") != std::string::npos);
    const std::string json = read_all(dir / "summary.json");
    CHECK(json.find("\"source\": \"pencil\"") != std::string::npos);
    CHECK(json.find("the sweep stopped at 2400 rpm") != std::string::npos);
    std::filesystem::remove_all(dir);
}
