// The Campbell sweep (src/analyses/campbell/campbell.hpp): crossings of the
// excitation lines, the sweep at rest against today's solve, tracks and whirl
// of the rotation tester (case 12), its critical speeds against a solve at
// the crossing speed.
#include "analyses/campbell/campbell.hpp"

#include "beam/beam_model.hpp"
#include "beam/beam_network.hpp"
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

// A rigid rotor on two radial springs (tests/unit/beam/test_rotating_modes.cpp):
// 0.5 m, 10 kg, transverse inertia Id about its centre, polar Ip = 1.6 Id,
// the beam 1e7 times stiffer than the springs (k = 1e6 N/m each).
struct RigidRotor {
    double L = 0.5, m = 10.0, k = 1e6, Id = 0, Ip = 0;
    BeamNetwork network;

    RigidRotor() {
        BeamSection s;
        s.rho_A = m / L;
        s.rho_I = 0.01;
        Id = s.rho_I * L + m * L * L / 12;
        Ip = 1.6 * Id;
        s.rho_J = Ip / L;
        s.EI = s.kappa_GA = s.EA = s.GJ = 1e7 * k * L * L * L;
        std::vector<double> z;
        for (int i = 0; i <= 4; ++i) z.push_back(L * i / 4);
        network.add_beam("rotor", z, std::vector<BeamSection>(4, s), [&](double zi) { return network.add_node(zi); });
        Matrix6 spring = Matrix6::Zero();
        spring(beam_dof::ux, beam_dof::ux) = spring(beam_dof::uy, beam_dof::uy) = k;
        for (int node : {network.beams[0].nodes.front(), network.beams[0].nodes.back()})
            network.springs.push_back({node, -1, spring});
    }
    // Where f = order f_rot meets the conical whirl, Id w^2 -+ Ip Omega w - k_t = 0
    // with w = order Omega: Omega^2 (order^2 Id -+ order Ip) = k_t (Hz).
    double conical_crossing_hz(int order, int sign) const {
        const double k_tilt = 2 * k * (L / 2) * (L / 2);
        return std::sqrt(k_tilt / (order * order * Id - sign * order * Ip)) / (2 * M_PI);
    }
    // The bounce mode (translation) does not feel the spin: sqrt(2 k / m) / order.
    double bounce_crossing_hz(int order) const { return std::sqrt(2 * k / m) / (2 * M_PI) / order; }
};

}  // namespace

TEST_CASE("Refined critical speeds meet the closed form where the sweep's interpolation does not",
          "[rotation][campbell]") {
    // The disc-like rigid rotor's conical whirl bends strongly with speed
    // (Ip = 1.6 Id): its crossings with f = k f_rot are the roots of a
    // quadratic, and a sweep 20 Hz apart misses them by 0.07 to 0.15 %
    // when it interpolates linearly. Refined: to kCrossingSpeedTolerance
    // (1e-6) plus what the beam's own elasticity leaves of the rigid rotor:
    // measured 1e-8 to 4e-8 on the backward whirl and the bounce, 2e-6 on
    // the forward whirl at 272 Hz (the rigid-rotor test of the beam level
    // sees a few 1e-6 at 417 Hz), so 1e-6 and 3e-6. The bounce mode does not
    // feel the spin: a flat curve, which the interpolation already meets.
    const RigidRotor rotor;
    const RotatingNetwork network(rotor.network, 2 * rotor.k / rotor.m);
    RotationSpec rotation;
    for (int i = 0; i <= 8; ++i) rotation.speeds_hz.push_back(20.0 * i);
    CampbellResult out;
    out.excitation_orders = {1, 2};
    out.roll_outer_diameter = 0.1;
    const int window = 12;
    campbell_sweep(network.modes_at(0.0, window), 8, [&](double s) { return network.modes_at(s, window); }, rotation,
                   out);
    struct Expected {
        int order;
        Whirl whirl;
        double speed_hz;
        bool curved;  // the conical whirl: the interpolation misses it
        double tolerance;
    };
    const std::vector<Expected> expected{{2, Whirl::backward, rotor.conical_crossing_hz(2, -1), true, 1e-6},
                                         {1, Whirl::backward, rotor.conical_crossing_hz(1, -1), true, 1e-6},
                                         {2, Whirl::forward, rotor.conical_crossing_hz(2, +1), true, 3e-6},
                                         {2, Whirl::none, rotor.bounce_crossing_hz(2), false, 1e-6},
                                         {1, Whirl::none, rotor.bounce_crossing_hz(1), false, 1e-6}};
    for (const Expected& e : expected) {
        INFO("order " << e.order << " at " << e.speed_hz << " Hz (" << whirl_name(e.whirl) << ")");
        const WhirlCrossing* found = nullptr;
        for (const WhirlCrossing& c : out.critical)
            if (c.order == e.order && std::abs(c.speed_hz - e.speed_hz) < 0.05 * e.speed_hz) found = &c;
        REQUIRE(found);
        INFO("refined: relative error " << found->speed_hz / e.speed_hz - 1 << " in " << found->refinement_solves
                                        << " solves; interpolated: " << found->interpolated_speed_hz / e.speed_hz - 1);
        CHECK(found->refined);
        CHECK(found->speed_hz == Approx(e.speed_hz).epsilon(e.tolerance));
        if (e.whirl != Whirl::none) CHECK(found->whirl == e.whirl);
        CHECK(found->high_speed_hz - found->low_speed_hz <= kCrossingSpeedTolerance * found->high_speed_hz);
        CHECK(found->refinement_solves <= 12);
        if (e.curved) CHECK(std::abs(found->interpolated_speed_hz - e.speed_hz) > 100 * e.tolerance * e.speed_hz);
    }
}

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
    const RotatingNetwork network(rest.network, rest.lambda_scale);
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
    c.scene.model = ModelChoice::solid;
    c.scene.mesh.file = "no-such-mesh.msh";  // never read: the check comes first
    CHECK_THROWS_WITH(run_campbell(c.scene, RotationSpec{.speeds_hz = {0.0, 10.0}}),
                      Catch::Contains("[rotation] at the solid level") && Catch::Contains("not expanded") &&
                          Catch::Contains("time-periodic"));
}
