// The harmonic level of a spinning scene (models/harmonic/rotating_harmonics)
// against independent truths: Bryan's factor of a thin spinning ring (the
// travelling waves of wave number n split by 2 n (n^2 - 1) / (n^2 + 1) f_rot
// in the stationary frame), the beam level's forward/backward whirl of a
// spinning tube (the same gyroscopic physics at another level), and at
// rest the harmonic level's own modes.
#include "analyses/campbell/campbell.hpp"
#include "eigensolve/projected_gyroscopic.hpp"
#include "beam/beam_model.hpp"
#include "beam/rotating_modes.hpp"
#include "models/harmonic/rotating_harmonics.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace coremodal;

namespace {

// The lowest mode of a type, wave number and whirl.
const RotatingMode& first(const std::vector<RotatingMode>& modes, const std::string& type, int n, Whirl whirl) {
    for (const RotatingMode& m : modes)
        if (m.label.type == type && m.label.n == n && m.whirl == whirl) return m;
    FAIL("no " << type << " n = " << n << " mode with whirl " << whirl_name(whirl));
    throw;
}

}  // namespace

TEST_CASE("A thin spinning ring: travelling waves split by Bryan's factor", "[rotation][harmonic]") {
    // Steel ring R ~ 0.5 m, t = 5 mm (t/R = 0.01), 20 mm long, free: in-plane
    // ovalling n = 2 at ~13 Hz. At f_rot = 0.1 Hz the stationary-frame
    // waves split by 2 f_rot n (n^2 - 1) / (n^2 + 1): Bryan (1890) for an
    // inextensible thin ring; the shell's extensibility and thickness change
    // it by O((t/R)^2) ~ 1e-4, the mesh by less (measured: 2e-5 at n = 2 and 3).
    Scene ring = testing::steel_tube(1.0, 0.99, 0.02, 2, 64, 2, 16);
    ring.model = "harmonic";
    const RotatingHarmonics harmonics(ring, 16);
    const double f_rot = 0.1;
    const std::vector<RotatingMode> modes = harmonics.modes_at(f_rot);
    for (int n : {2, 3}) {
        const RotatingMode& fw = first(modes, "ovalling", n, Whirl::forward);
        const RotatingMode& bw = first(modes, "ovalling", n, Whirl::backward);
        const double bryan = n * (n * n - 1.0) / (n * n + 1.0);
        INFO("n = " << n << ": FW " << fw.frequency_hz << " Hz, BW " << bw.frequency_hz << " Hz");
        CHECK((fw.frequency_hz - bw.frequency_hz) / (2 * f_rot) == Approx(bryan).epsilon(2e-4));
        CHECK(fw.relative_residual < 1e-9);
        CHECK(bw.relative_residual < 1e-9);
    }
}

TEST_CASE("A spinning clamped tube whirls at the harmonic level as at the beam level", "[rotation][harmonic]") {
    // Steel 106 x 76 mm, 1.2 m, clamped over 40 mm at both ends, spinning at
    // its first bending frequency at rest: the forward/backward split of the
    // first bending pair from the gyroscopic term rho_J (beam) and from the
    // spinning section (harmonic) agree to the two levels' difference in
    // the clamp's stiffness and the wall's shear (1.3 % measured).
    Scene tube = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 1.2, 2, 16, 24, 8), 0.04);
    tube.model = "harmonic";
    const RotatingHarmonics harmonics(tube, 8);
    const double f1 = first(harmonics.modes_at(0.0), "bending", 1, Whirl::none).frequency_hz;
    const std::vector<RotatingMode> spinning = harmonics.modes_at(f1);
    const RotatingMode& fw = first(spinning, "bending", 1, Whirl::forward);
    const RotatingMode& bw = first(spinning, "bending", 1, Whirl::backward);

    Scene beam = tube;
    beam.model = "beam";
    const BeamModelResult rest = solve_beam_model(beam);
    const std::vector<RotatingMode> beam_modes = RotatingNetwork(rest.network, rest.lambda_scale).modes_at(f1, 8);
    const RotatingMode& beam_fw = first(beam_modes, "bending", 1, Whirl::forward);
    const RotatingMode& beam_bw = first(beam_modes, "bending", 1, Whirl::backward);

    const double split = (fw.frequency_hz - bw.frequency_hz) / (fw.frequency_hz + bw.frequency_hz);
    const double beam_split =
        (beam_fw.frequency_hz - beam_bw.frequency_hz) / (beam_fw.frequency_hz + beam_bw.frequency_hz);
    INFO("harmonic FW " << fw.frequency_hz << " BW " << bw.frequency_hz << "; beam FW " << beam_fw.frequency_hz
                        << " BW " << beam_bw.frequency_hz);
    CHECK(split > 0);
    CHECK(split == Approx(beam_split).epsilon(0.03));
    CHECK(fw.relative_residual < 1e-9);
}

TEST_CASE("At rest the spinning harmonic level gives the harmonic level's modes", "[rotation][harmonic]") {
    // A paper core on chucks with spring layers and elastic bearings with
    // frames: every term of the harmonic level.
    Scene s = testing::on_elastic_bearings(
        testing::with_chucks(testing::paper_core(0.8, 16, 12), InterfaceKind::spring), 3e8, 4e6, 25.0, 6e7);
    s.model = "harmonic";
    s.analysis.n_modes = 10;
    const RunReport run = testing::solve_quietly(s);
    const RotatingHarmonics harmonics(s, 10, true);  // the centrifugal term is nothing at rest
    const std::vector<RotatingMode> modes = harmonics.modes_at(0.0);
    REQUIRE(modes.size() == run.modes.modes.size());
    for (size_t i = 0; i < modes.size(); ++i) {
        INFO("mode " << i + 1);
        CHECK(modes[i].frequency_hz == Approx(run.modes.modes[i].frequency_hz).epsilon(1e-8));
        CHECK(modes[i].label.type == run.modes.modes[i].label.type);
        CHECK(modes[i].label.n == run.modes.modes[i].label.n);
    }
}

namespace {

// The projected path (a basis per n, verified and counted on the full set)
// against the full PEP at every speed: the same modes. 1e-8: both are
// solves of one quadratic problem to residuals below kMaxProjectedResidual,
// and a Hermitian problem's frequencies are accurate to about the square of
// that; the rigid modes are reported at 0 Hz by both. A free body's slow
// precession (Omega I_p / I_t) is a near-double zero of the quadratic
// problem, which TOAR resolves only to ~sqrt(eps) of its scale (tolerances.hpp;
// measured: the two paths differ by 3e-8 to 3e-5 there): compared to 1e-4.
void check_same_modes(const Scene& scene, int window, const std::vector<double>& speeds_hz, double tolerance,
                      double precession_hz = 0, bool centrifugal = false) {
    RotatingHarmonics projected(scene, window, centrifugal, SpinSolver::projected);
    // The rigid line counted once for the sweep where convexity proves it
    // clear (the tube: every n; the free ring: its n >= 2 only).
    projected.sweep_up_to(speeds_hz.back());
    const RotatingHarmonics full(scene, window, centrifugal, SpinSolver::full);
    for (double speed : speeds_hz) {
        const std::vector<RotatingMode> a = projected.modes_at(speed), b = full.modes_at(speed);
        REQUIRE(a.size() == b.size());
        for (size_t i = 0; i < a.size(); ++i) {
            INFO("speed " << speed << " Hz, mode " << i + 1 << ": " << a[i].frequency_hz << " / " << b[i].frequency_hz << " Hz");
            CHECK(a[i].block == b[i].block);
            const bool precession = a[i].block == 1 && std::abs(a[i].frequency_hz - precession_hz * speed) < 0.01 * speed;
            CHECK(a[i].frequency_hz == Approx(b[i].frequency_hz).epsilon(precession ? 1e-4 : tolerance).margin(1e-12));
            CHECK(a[i].relative_residual < (a[i].frequency_hz > 0 ? kMaxProjectedResidual : kMaxRigidModeResidual));
            if (a[i].frequency_hz > 0 && speed > 0) CHECK(a[i].whirl == b[i].whirl);
        }
    }
    // The basis answered (verified and counted complete on the full set) all
    // but a few problems: the tube's ring modes of n = 2, 3 at 11-12 kHz, in
    // its window of 8, reach residuals of 1e-8 to 2e-8 at speed and are
    // solved whole, as they must be.
    INFO(projected.n_full_solves() << " of " << projected.n_solves() << " solved whole");
    CHECK(projected.n_solves() == long(speeds_hz.size() * projected.wave_numbers().size()));
    CHECK(projected.n_full_solves() <= projected.n_solves() / 4);
}

}  // namespace

TEST_CASE("Spinning harmonics in a projection basis: the full quadratic solver's modes, proven complete",
          "[rotation][harmonic]") {
    SECTION("A clamped steel tube from rest to its first bending frequency (415 Hz)") {
        Scene tube = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 1.2, 2, 16, 24, 8), 0.04);
        tube.model = "harmonic";
        check_same_modes(tube, 8, {0.0, 50.0, 150.0, 415.0}, 1e-8);
    }
    SECTION("The same tube with centrifugal stiffening (K_Omega projected with the rest)") {
        Scene tube = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 1.2, 2, 16, 24, 8), 0.04);
        tube.model = "harmonic";
        check_same_modes(tube, 8, {0.0, 150.0, 415.0}, 1e-8, 0, true);
    }
    SECTION("A free thin ring: rigid modes, the slow precession and Bryan's waves") {
        // t/R = 0.01: bending eigenvalues 1e-9 of the membrane's, so both
        // solvers resolve them only to ~1e-7 (each splits the exact pairs
        // at rest by that much): compared to 1e-6.
        Scene ring = testing::steel_tube(1.0, 0.99, 0.02, 2, 64, 2, 16);
        ring.model = "harmonic";
        check_same_modes(ring, 16, {0.0, 0.1, 1.0, 5.0}, 1e-6, 2.0);  // I_p = 2 I_t, thin
    }
}
