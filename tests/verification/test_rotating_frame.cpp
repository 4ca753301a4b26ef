// The solid level's co-rotating path (models/solid/rotating_frame,
// docs/theory/rotation-solid.md "Scenes that are not bodies of revolution"). The
// strongest truth it has is the stationary-frame path: on a body of
// revolution both are exact, with different gyroscopic matrices (G_c =
// 2 int rho N^T J N dV against element_gyroscopic's L) and different
// Omega^2 terms (-M_P against -M_L), so the same stationary frequencies
// mode by mode check both. Then a scene only the rotating frame can spin
// (three expanding segments per chuck): at rest the solid run's modes.
#include "analyses/campbell/campbell.hpp"
#include "models/solid/rotating_frame.hpp"
#include "models/solid/rotating_solid.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include "scene/case_file.hpp"
#include "scene/mesh_levels.hpp"

#include <algorithm>
#include <cmath>

using namespace coremodal;

TEST_CASE("A body of revolution spun in the rotating frame has the stationary frame's frequencies, mode by mode",
          "[rotation][solid][rotating_frame]") {
    // A clamped steel tube (106 x 76 mm, 0.6 m, clamped over 30 mm), 1 x 16 x 8
    // hex20, at f_rot = 0.3 f1 with the centrifugal term, in both frames.
    Scene tube = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 0.6, 1, 16, 8, 10), 0.03);
    tube.model = ModelChoice::solid;
    const RotatingSolid stationary(tube, 10, {.frame = SpinFrame::stationary, .centrifugal_stiffening = true});
    const RotatingSolid rotating(tube, 10, {.frame = SpinFrame::rotating, .centrifugal_stiffening = true});
    REQUIRE(rotating.rotating_frame());
    const std::vector<RotatingMode> rest = stationary.modes_at(0.0);
    const double f_rot = 0.3 * rest.front().frequency_hz;
    const std::vector<RotatingMode> s = stationary.modes_at(f_rot);
    const std::vector<RotatingMode> r = rotating.modes_at(f_rot);
    REQUIRE(r.size() >= 8);
    // Both frames are exact for the continuum; on the mesh the stationary
    // frame's d/dtheta of the shape functions is the discretised one, so
    // the two differ by a share of the shift n f_rot that falls with the
    // cells around: measured 4.6e-5 on 16 cells, 5.9e-6 on 32 (h^3); the
    // bending pairs agree to 1e-7. Tolerance: twice the 16-cell value.
    constexpr double kFrameShiftTolerance = 1e-4;
    double worst = 0;
    for (size_t i = 0; i < 8; ++i) {
        INFO("mode " << i + 1 << " (" << s[i].label.type << " n = " << s[i].label.n << "): stationary "
                     << s[i].frequency_hz << " Hz " << whirl_name(s[i].whirl) << ", rotating frame brought back "
                     << r[i].frequency_hz << " Hz " << whirl_name(r[i].whirl));
        // The two frames' difference as a share of the frames' shift n f_rot.
        const double share = std::abs(r[i].frequency_hz - s[i].frequency_hz) / (std::max(1, s[i].label.n) * f_rot);
        worst = std::max(worst, share);
        CHECK(share < kFrameShiftTolerance);
        CHECK(r[i].whirl == s[i].whirl);
        CHECK(r[i].label.n == s[i].label.n);
    }
    INFO("largest relative difference " << worst << "; smallest dominant-harmonic share " << rotating.min_harmonic_share());
    CHECK(rotating.min_harmonic_share() > 0.99);
    CHECK(rotating.max_relative_residual() < 1e-8);
}

TEST_CASE("Three expanding segments per chuck spin in the rotating frame; at rest the solid run's modes",
          "[rotation][solid][rotating_frame][long]") {
    Scene s = testing::with_chucks(testing::paper_core(0.8, 12, 8), InterfaceKind::spring);
    for (ChuckSpec& c : s.supports.chucks) c.expanding[0].segments = 3, c.expanding[0].segment_angle = M_PI / 3;
    s.model = ModelChoice::solid;
    s.analysis.n_modes = 8;
    const RunReport run = testing::solve_without_chuck_factor(s);
    const RotatingSolid solid(s, 8, {.centrifugal_stiffening = true});
    REQUIRE(solid.rotating_frame());
    const std::vector<RotatingMode> rest = solid.modes_at(0.0);
    REQUIRE(rest.size() == 8);  // the run adds the partner of its last pair
    for (size_t i = 0; i < rest.size(); ++i) {
        INFO("mode " << i + 1 << ": " << rest[i].frequency_hz << " Hz, run " << run.modes.modes[i].frequency_hz);
        CHECK(rest[i].frequency_hz == Approx(run.modes.modes[i].frequency_hz).epsilon(1e-8));
        CHECK(rest[i].label.type == run.modes.modes[i].label.type);
        CHECK(rest[i].whirl == Whirl::none);
    }
    // Spinning at half the first frequency: verified modes, forward and
    // backward members of the first bending pair around the rest value.
    const double f1 = rest.front().frequency_hz;
    const std::vector<RotatingMode> spin = solid.modes_at(0.5 * f1);
    CHECK(solid.max_relative_residual() < 1e-8);
    bool forward = false, backward = false;
    for (const RotatingMode& m : spin)
        if (m.label.type == "bending" && m.label.n == 1 && std::abs(m.frequency_hz / f1 - 1) < 0.05) {
            forward |= m.whirl == Whirl::forward;
            backward |= m.whirl == Whirl::backward;
        }
    CHECK(forward);
    CHECK(backward);
    // The segments mix each harmonic k with k +- 3: the conversion to the
    // stationary frame reads the dominant one (measured: at least 0.87 of
    // a mode's energy on the surface); above one half it is unambiguous.
    INFO("smallest dominant-harmonic share " << solid.min_harmonic_share());
    CHECK(solid.min_harmonic_share() > 0.5);
}

TEST_CASE("The solid level refuses to spin a chuck not expanded, and a bearing stiffer in x than in y",
          "[rotation][solid][rotating_frame]") {
    Scene s = testing::with_chucks(testing::paper_core(0.8, 12, 8), InterfaceKind::spring);
    s.supports.chucks[0].interface.contact = ContactKind::one_sided;
    s.model = ModelChoice::solid;
    CHECK_THROWS_WITH(RotatingSolid(s, 6), Catch::Contains("not expanded") && Catch::Contains("time-periodic"));
    ChuckSupports supports;
    supports.grounded = {0};
    supports.couplings.push_back({{0}, {{Term::stiffness, Eigen::Vector3d(1e6, 2e6, 1e6).asDiagonal().toDenseMatrix()}}});
    CHECK(anisotropic_support(supports).value_or("") ==
          "a support to the stand (a bearing or frame spring, or the web's span) differs in x and y");
    supports.couplings[0].terms[0].matrix = Eigen::Vector3d(1e6, 1e6, 3e6).asDiagonal().toDenseMatrix();
    CHECK_FALSE(anisotropic_support(supports));
}

TEST_CASE("Case 10 spins at the solid level on the coarse mesh: at rest the solid run's modes, then its Campbell notes",
          "[rotation][solid][rotating_frame][long]") {
    // Three 60-degree segments per chuck on the coarse mesh (30,300 DOFs):
    // refused before the rotating frame; now the sweep runs, its modes at
    // rest are today's solid run's (measured: every frequency to 2e-10),
    // and the notes say how the frequencies came to the stationary frame.
    Scene scene = parse_case_file(COREMODAL_SOURCE_DIR "/cases/10-segmented-chuck-76x15-2200.toml");
    apply_mesh_level(scene, "coarse");
    scene.model = ModelChoice::solid;
    scene.analysis.n_modes = 4;  // the bending pairs m = 0 and 1: the window is what the test pays for
    RotationSpec rotation;
    rotation.speeds_hz = {0.0, 20.0};
    // No excitation lines: the pencils r > 0 and the crossings' refinement
    // (tested on segmented chucks in test_rotating_frame_critical.cpp) are not what
    // this test checks, and were over a third of its time (101 -> 64 s alone).
    rotation.excitation_orders = {};
    const CampbellResult campbell = run_campbell(scene, rotation);
    const RunReport run = testing::solve_without_chuck_factor(scene);
    REQUIRE(campbell.points.size() == 2);
    const std::vector<CampbellMode>& rest = campbell.points[0].modes;
    REQUIRE(rest.size() <= run.modes.modes.size());
    for (size_t i = 0; i < rest.size(); ++i) {
        INFO("mode " << i + 1 << ": " << rest[i].frequency_hz << " Hz, run " << run.modes.modes[i].frequency_hz);
        CHECK(rest[i].frequency_hz == Approx(run.modes.modes[i].frequency_hz).epsilon(1e-8));
    }
    CHECK(campbell.max_relative_residual < 1e-8);
    const auto noted = [&](const std::string& words) {
        return std::any_of(campbell.notes.begin(), campbell.notes.end(),
                           [&](const std::string& n) { return n.find(words) != std::string::npos; });
    };
    CHECK(noted("co-rotating coordinates"));
    CHECK(noted("dominant harmonic's share"));
    CHECK(std::find(campbell.effects.begin(), campbell.effects.end(), "centrifugal_stiffening") != campbell.effects.end());
}

TEST_CASE("Above the first forward critical speed the rotating frame's stiffness is indefinite: refused, with the speed",
          "[rotation][solid][rotating_frame]") {
    // The clamped steel tube of the first test, in co-rotating coordinates.
    // There K(Omega) = K + Omega^2 (K_sigma1 - M_P); on the first bending
    // pair's forward whirl it is k - Omega^2 m (a Jeffcott rotor seen from
    // its own axes), so it turns negative where f_rot passes that whirl's
    // stationary frequency: at 1.3 f1 it is about -0.7 k, far below the
    // rigid line's -omega_0^2 (1e-4 of the first eigenvalue). The
    // completeness count assumes K(Omega) + omega_0^2 M >= 0
    // (gyroscopic_solver.hpp): no modes at that speed, and the message says
    // which speed and why. Below it (0.8 f1) the frame solves as before.
    Scene tube = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 0.6, 1, 16, 8, 10), 0.03);
    tube.model = ModelChoice::solid;
    const RotatingSolid rotating(tube, 6, {.frame = SpinFrame::rotating, .centrifugal_stiffening = true});
    const double f1 = rotating.modes_at(0.0).front().frequency_hz;
    CHECK_NOTHROW(rotating.modes_at(0.8 * f1));
    const double rpm = 1.3 * f1 * 60;
    CHECK_THROWS_WITH(rotating.modes_at(1.3 * f1),
                      Catch::Contains("is indefinite") && Catch::Contains(std::to_string(rpm).substr(0, 5)) &&
                          Catch::Contains("no modes are reported") && Catch::Contains("below this speed"));
}
