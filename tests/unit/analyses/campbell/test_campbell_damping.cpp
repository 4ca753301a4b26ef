// The damped modes of a Campbell sweep ([damping], analyses/campbell) at the
// harmonic level against closed forms: at rest, Rayleigh damping
// D = alpha M + beta K is diagonal in the modes at rest, so every mode keeps
// its shape and natural frequency and takes zeta_j = alpha / (2 omega_j) +
// beta omega_j / 2 (Chopra, Dynamics of Structures, ch. 11); a uniform loss
// factor (H = eta K on a clamped tube: no springs) gives every mode
// lambda = i omega sqrt(1 + i eta), zeta = sin(atan(eta) / 2) and
// |lambda| = omega (1 + eta^2)^(1/4) (eigensolve/damped_modes.hpp). Spinning,
// the damped frequencies tend to the undamped sweep's as the damping goes to
// 0, at second order (the first-order shift of a symmetric D on a
// gyroscopic mode is real: x^H G x is imaginary for a skew G).
#include "analyses/campbell/campbell.hpp"

#include "common/error.hpp"
#include "scene/response_spec.hpp"

#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace coremodal;

namespace {

// The rotation tester's core (case 12, tests/support/tiny_case.hpp) at the
// harmonic level on a coarse section: 6 modes at rest, first bending pair ~62 Hz.
std::string tester(const std::string& damping, const std::string& model = "harmonic") {
    std::string core = testing::kClampedTesterCore;
    core.replace(core.find("model = \"beam\""), 14, "model = \"" + model + "\"");
    return core + R"([mesh]
along = 24
through_wall = 1
[rotation]
speeds = ["0 rpm", "2000 rpm"]
points = 2
[damping]
)" + damping + "\n";
}

CampbellResult campbell_of(const std::string& text, std::vector<double> speeds_hz) {
    ResponseCase c = parse_response_case_text(text, "damped.toml");
    REQUIRE(c.damping);
    RotationSpec rotation = *c.rotation;
    rotation.speeds_hz = std::move(speeds_hz);
    return run_campbell(c.scene, rotation, &*c.damping);
}

// The eigenvalue's relative error |d lambda| / |lambda|: zeta = -Re lambda / |lambda|
// moves by at most that much (absolute), the damped frequency by that much
// relative. The residual (at most 1e-8, checked; 2e-9 measured) bounds it
// times the mode's condition, which for the lowest modes is large (the
// residual is scaled by ||K||, the stiffest mode's): measured 1e-7 on the
// degenerate pairs at rest, within the 1e-6 every verified mode meets.
constexpr double kTolerance = 1e-6;

}  // namespace

TEST_CASE("Rayleigh damping at rest: zeta_j = alpha / (2 omega_j) + beta omega_j / 2 for every mode",
          "[campbell][damping]") {
    const double alpha = 2.0, beta = 5e-5;
    const CampbellResult r = campbell_of(tester("rayleigh = { alpha = 2.0, beta = 5e-5 }"), {0.0});
    REQUIRE(r.damped);
    CHECK(r.max_damped_residual < 1e-8);
    REQUIRE(r.points.size() == 1);
    REQUIRE(r.points[0].modes.size() == 6);
    for (const CampbellMode& m : r.points[0].modes) {
        const double omega = 2 * M_PI * m.frequency_hz, zeta = alpha / (2 * omega) + beta * omega / 2;
        INFO(m.frequency_hz << " Hz");
        REQUIRE(m.damping_ratio);
        CHECK(std::abs(*m.damping_ratio - zeta) < kTolerance);
        CHECK(*m.damped_frequency_hz == Approx(m.frequency_hz * std::sqrt(1 - zeta * zeta)).epsilon(kTolerance));
    }
    CHECK(std::find(r.effects.begin(), r.effects.end(), "rayleigh_damping") != r.effects.end());
}

TEST_CASE("A uniform loss factor at rest: zeta = sin(atan(eta) / 2) for every mode", "[campbell][damping]") {
    const double eta = 0.04;
    const CampbellResult r = campbell_of(tester("loss_factor = 0.04"), {0.0});
    CHECK(r.max_damped_residual < 1e-8);
    REQUIRE(r.points[0].modes.size() == 6);
    for (const CampbellMode& m : r.points[0].modes) {
        INFO(m.frequency_hz << " Hz");
        REQUIRE(m.damping_ratio);
        CHECK(std::abs(*m.damping_ratio - std::sin(std::atan(eta) / 2)) < kTolerance);
        // Im lambda = omega (1 + eta^2)^(1/4) cos(atan(eta) / 2).
        CHECK(
            *m.damped_frequency_hz ==
            Approx(m.frequency_hz * std::pow(1 + eta * eta, 0.25) * std::cos(std::atan(eta) / 2)).epsilon(kTolerance));
    }
}

TEST_CASE("Spinning: the damped frequencies tend to the undamped sweep's at second order in the damping",
          "[campbell][damping]") {
    const double f_rot = 2000.0 / 60;
    double previous_gap = 0;
    for (const double scale : {1.0, 0.1}) {
        const std::string rayleigh =
            "rayleigh = { alpha = " + std::to_string(2.0 * scale) + ", beta = " + std::to_string(5e-5 * scale) + " }";
        const CampbellResult r = campbell_of(tester(rayleigh), {0.0, f_rot});
        CHECK(r.max_damped_residual < 1e-8);
        double gap = 0;  // the largest relative gap at speed
        for (const CampbellMode& m : r.points.back().modes) {
            REQUIRE(m.damping_ratio);
            CHECK(*m.damping_ratio > 0);
            gap = std::max(gap, std::abs(*m.damped_frequency_hz - m.frequency_hz) / m.frequency_hz);
        }
        INFO("scale " << scale << ": gap " << gap);
        CHECK(gap < 2e-3 * scale * scale);                     // zeta <= 0.06: zeta^2 / 2 < 2e-3
        if (previous_gap > 0) CHECK(gap < previous_gap / 30);  // second order: 1/100 for a tenth of the damping
        previous_gap = gap;
    }
}

TEST_CASE("A Campbell sweep refuses damping it cannot carry, saying which level and which form can",
          "[campbell][damping]") {
    const ResponseCase beam = parse_response_case_text(tester("loss_factor = 0.02", "beam"), "damped.toml");
    CHECK_THROWS_WITH(require_campbell_damping(beam.scene, *beam.damping),
                      Catch::Contains("model = \"beam\"") && Catch::Contains("model = \"harmonic\""));
    const ResponseCase modal = parse_response_case_text(tester("ratio = 0.01"), "damped.toml");
    CHECK_THROWS_WITH(require_campbell_damping(modal.scene, *modal.damping),
                      Catch::Contains("[damping] ratio = 0.01") && Catch::Contains("rayleigh = { zeta = 0.01"));
    // Without [rotation] (nor [response]) [damping] damps nothing and is refused by the reader.
    std::string no_rotation = tester("ratio = 0.01");
    no_rotation.replace(no_rotation.find("[rotation]"), no_rotation.find("[damping]") - no_rotation.find("[rotation]"),
                        "");
    CHECK_THROWS_WITH(parse_response_case_text(no_rotation, "damped.toml"),
                      Catch::Contains("[damping] is used only by the forced response and the Campbell diagram"));
}
