// The Campbell sweep (src/analyses/campbell/campbell.hpp): crossings of the
// excitation lines, the sweep at rest against today's solve, tracks and whirl
// of the rotation tester (case 12), its critical speeds against a solve at
// the crossing speed.
#include "analyses/campbell/campbell.hpp"

#include "beam/rotating_modes.hpp"
#include "common/error.hpp"
#include "scene/rotation_spec.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace coremodal;

namespace {

RotatingCase tester(int points) {
    RotatingCase c = parse_rotating_case(std::string(COREMODAL_SOURCE_DIR) + "/cases/12-rotation-tester-76x15.toml");
    const double last = c.rotation->speeds_hz.back();
    c.rotation->speeds_hz.clear();
    for (int i = 0; i < points; ++i) c.rotation->speeds_hz.push_back(last * i / (points - 1));
    return c;
}

}  // namespace

TEST_CASE("Critical speeds: where f = k f_rot crosses a tracked frequency, in rpm and web speed", "[rotation][campbell]") {
    // One flat track at 10 Hz, speeds 0, 4, 8, 12 Hz: order 1 crosses at 10 Hz,
    // order 2 at 5 Hz (linear between 4 and 8 Hz: exact for a flat curve).
    std::vector<CampbellPoint> points;
    for (double s : {0.0, 4.0, 8.0, 12.0}) points.push_back({s, {{7, 10.0, Whirl::forward, {"bending", 1, 0, 1}, 0}}});
    const double dp = 0.106;
    const std::vector<WhirlCrossing> c = critical_speeds(points, {1, 2}, dp);
    REQUIRE(c.size() == 2);
    CHECK(c[0].order == 2);
    CHECK(c[0].speed_hz == Approx(5.0));
    CHECK(c[0].frequency_hz == Approx(10.0));
    CHECK(c[1].order == 1);
    CHECK(c[1].speed_hz == Approx(10.0));
    CHECK(c[1].web_speed_m_s == Approx(M_PI * dp * 10.0));
    CHECK(c[1].track == 7);
    CHECK(c[1].whirl == Whirl::forward);
}

TEST_CASE("The rotation tester's Campbell sweep: rest exactly, whirl split, critical speeds", "[rotation][campbell]") {
    const RotatingCase c = tester(9);  // 0 to 4000 rpm in 500 rpm steps
    const Scene& scene = c.scene;
    const CampbellResult r = run_campbell(scene, *c.rotation);
    REQUIRE(r.points.size() == 9);
    // At rest: the beam level's modes, exactly.
    const BeamModelResult rest = solve_beam_model(scene);
    REQUIRE(r.points[0].modes.size() == rest.modes.size());
    for (size_t i = 0; i < rest.modes.size(); ++i) CHECK(r.points[0].modes[i].frequency_hz == rest.modes[i].frequency_hz);
    CHECK(r.max_relative_residual < 1e-9);
    // The first bending pair splits: its forward whirl rises, its backward whirl falls.
    const int fw_track = r.points.back().modes[0].whirl == Whirl::forward ? r.points.back().modes[0].track
                                                                         : r.points.back().modes[1].track;
    const auto at = [&](const CampbellPoint& p, int track) {
        for (const CampbellMode& m : p.modes)
            if (m.track == track) return m.frequency_hz;
        return -1.0;
    };
    CHECK(at(r.points.back(), fw_track) > at(r.points[0], fw_track));
    CHECK(r.points.back().modes[0].whirl == Whirl::backward);
    CHECK(r.points.back().modes[0].label.type == "bending");
    // Orders 1 and 2 cross the first bending pair; each crossing checked
    // against a solve at the crossing speed (linear interpolation between
    // 500 rpm steps of nearly flat curves).
    const RotatingNetwork network(r.rest.network, r.rest.lambda_scale);
    int order_one = 0, order_two = 0;
    for (const WhirlCrossing& c : r.critical) {
        if (c.label.type != "bending" || c.label.m != 0) continue;
        (c.order == 1 ? order_one : order_two)++;
        double nearest = 1e300;
        for (const RotatingMode& m : network.modes_at(c.speed_hz, 12))
            nearest = std::min(nearest, std::abs(m.frequency_hz - c.frequency_hz));
        CHECK(nearest < 1e-3 * c.frequency_hz);
    }
    CHECK(order_two == 2);  // BW and FW of the first pair
    CHECK(order_one >= 1);
    REQUIRE(r.first_order_one());
    CHECK(r.first_order_one()->speed_hz == Approx(r.points[0].modes[0].frequency_hz).epsilon(0.02));
    REQUIRE(r.speeds_at_rest.given());
    CHECK(r.speeds_at_rest.safe.front().v_safe_m_s == Approx(0.7 * M_PI * 0.106 * rest.modes[0].frequency_hz));
}

TEST_CASE("A Campbell sweep at the solid level refuses a chuck that is not expanded, before any work",
          "[rotation][campbell]") {
    RotatingCase c = parse_rotating_case(std::string(COREMODAL_SOURCE_DIR) +
                                         "/cases/09-news-chucks-not-expanded-76x15-2200.toml");
    c.scene.model = "solid";
    c.scene.mesh.file = "no-such-mesh.msh";  // never read: the check comes first
    CHECK_THROWS_WITH(run_campbell(c.scene, RotationSpec{.speeds_hz = {0.0, 10.0}}),
                      Catch::Contains("[rotation] at the solid level") && Catch::Contains("not expanded") &&
                          Catch::Contains("time-periodic"));
}
