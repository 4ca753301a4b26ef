// The solid level of a spinning scene (models/solid/rotating_solid) against
// independent truths: Bryan's factor of a thin spinning ring and the
// harmonic level's split on the same section (exact in theta, so the
// difference is the solid's circumferential discretisation, measured at rest
// first), the harmonic level's forward/backward whirl of a spinning tube, and
// at rest the solid run's own modes.
#include "beam/rotating_modes.hpp"
#include "models/harmonic/rotating_harmonics.hpp"
#include "models/solid/rotating_solid.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

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

double split_ratio(const RotatingMode& fw, const RotatingMode& bw) {
    return (fw.frequency_hz - bw.frequency_hz) / (fw.frequency_hz + bw.frequency_hz);
}

}  // namespace

TEST_CASE("A thin spinning ring at the solid level: the n = 2 waves split as Bryan and the harmonic level say",
          "[rotation][solid][long]") {
    // The harmonic level's ring (steel, R ~ 0.5 m, t/R = 0.01, 20 mm long,
    // free) on 128 hex20 cells around, 2 through the wall and 2 along. At
    // f_rot = 0.1 Hz Bryan's inextensible ring splits the n = 2 waves by
    // 2 f_rot x 1.2 in the stationary frame (the harmonic level: 1.20002).
    Scene ring = testing::steel_tube(1.0, 0.99, 0.02, 2, 128, 2, 16);
    const double f_rot = 0.1;
    ring.model = ModelChoice::harmonic;
    const RotatingHarmonics harmonics(ring, 16);
    const std::vector<RotatingMode> h_at_rest = harmonics.modes_at(0.0);
    const RotatingMode& h_rest = first(h_at_rest, "ovalling", 2, Whirl::none);
    const std::vector<RotatingMode> h_spin = harmonics.modes_at(f_rot);
    ring.model = ModelChoice::solid;
    const RotatingSolid solid(ring, 16);
    const std::vector<RotatingMode> s_at_rest = solid.modes_at(0.0);
    const RotatingMode& s_rest = first(s_at_rest, "ovalling", 2, Whirl::none);
    const std::vector<RotatingMode> s_spin = solid.modes_at(f_rot);
    const RotatingMode& fw = first(s_spin, "ovalling", 2, Whirl::forward);
    const RotatingMode& bw = first(s_spin, "ovalling", 2, Whirl::backward);
    const double bryan_solid = (fw.frequency_hz - bw.frequency_hz) / (2 * f_rot);
    const double bryan_harmonic = (first(h_spin, "ovalling", 2, Whirl::forward).frequency_hz -
                                   first(h_spin, "ovalling", 2, Whirl::backward).frequency_hz) / (2 * f_rot);
    // At rest the solid's n = 2 lies above the harmonic level's (exact in
    // theta) by its circumferential discretisation: measured 3.4e-3 on 128
    // cells around (16 % on 64: thin, long cells are too stiff in bending).
    // The split is a property of the wave's shape (V = U / n), which even
    // the coarse mesh keeps: measured 1.20002 on 64 and on 128 cells, as the
    // harmonic level. The tolerance is the frequency's error at rest.
    constexpr double kRestError = 5e-3;
    const double rest_error = s_rest.frequency_hz / h_rest.frequency_hz - 1;
    INFO("at rest: solid " << s_rest.frequency_hz << " Hz, harmonic " << h_rest.frequency_hz << " Hz ("
                           << rest_error << "); Bryan's factor: solid " << bryan_solid << ", harmonic "
                           << bryan_harmonic);
    CHECK(std::abs(rest_error) < kRestError);
    CHECK(bryan_solid == Approx(bryan_harmonic).epsilon(kRestError));
    CHECK(bryan_solid == Approx(1.2).epsilon(kRestError));
    // The solver accepts 1e-6; the solid's modes come to ~1e-9 (measured 1.3e-9).
    CHECK(fw.relative_residual < 1e-8);
    CHECK(bw.relative_residual < 1e-8);
}

TEST_CASE("A free ring whose rest solve makes LAPACK refuse TOAR's reordering is solved at another target",
          "[rotation][solid]") {
    // One cell through the wall and along, 128 around: at rest the six
    // rigid modes are double zeros of the quadratic problem (Jordan blocks),
    // and on this mesh LAPACK's trexc refused to reorder TOAR's Schur form
    // at the first target (measured; eigensolve/gyroscopic_solver.cpp
    // retries at others). The modes must still come, verified and complete.
    Scene ring = testing::steel_tube(1.0, 0.99, 0.02, 1, 128, 1, 16);
    ring.model = ModelChoice::solid;
    const RotatingSolid solid(ring, 16);
    const std::vector<RotatingMode> rest = solid.modes_at(0.0);
    CHECK(first(rest, "ovalling", 2, Whirl::none).frequency_hz == Approx(12.91).epsilon(1e-3));
    const std::vector<RotatingMode> spin = solid.modes_at(0.1);
    const double bryan = (first(spin, "ovalling", 2, Whirl::forward).frequency_hz -
                          first(spin, "ovalling", 2, Whirl::backward).frequency_hz) / 0.2;
    CHECK(bryan == Approx(1.2).epsilon(5e-3));
    // The solver accepts 1e-6. Measured 5.6e-9 with gmsh's higher-order nodes
    // and 1.13e-8 with them placed on their arcs from (r, theta, z) (issue 33,
    // geometry/tube_model.cpp): on this mesh, whose every higher-order node
    // lies on the surface, the two placements differ by 4e-10 m (round-off in
    // gmsh's curve parameter), and the ovalling pair by 3e-9: the residual of
    // this nearly defective problem (the rigid modes' double zeros) moves by
    // its own size under round-off. 1e-7 is about nine times the larger and
    // a tenth of what the solver accepts.
    CHECK(solid.max_relative_residual() < 1e-7);
}

TEST_CASE("A spinning clamped tube whirls at the solid level as at the harmonic level", "[rotation][solid][long]") {
    // The harmonic level's clamped steel tube (106 x 76 mm, 1.2 m, clamped
    // over 40 mm), 16 cells around, spinning at its first bending frequency:
    // forward whirl rises, backward falls, and the split matches the
    // harmonic level's on the same section.
    Scene tube = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 1.2, 2, 16, 24, 8), 0.04);
    tube.model = ModelChoice::harmonic;
    const RotatingHarmonics harmonics(tube, 8);
    const double f1 = first(harmonics.modes_at(0.0), "bending", 1, Whirl::none).frequency_hz;
    const std::vector<RotatingMode> h_spin = harmonics.modes_at(f1);
    tube.model = ModelChoice::solid;
    const RotatingSolid solid(tube, 8);
    const std::vector<RotatingMode> at_rest = solid.modes_at(0.0);
    const RotatingMode& rest = first(at_rest, "bending", 1, Whirl::none);
    const std::vector<RotatingMode> spin = solid.modes_at(f1);
    const RotatingMode& fw = first(spin, "bending", 1, Whirl::forward);
    const RotatingMode& bw = first(spin, "bending", 1, Whirl::backward);
    const double split = split_ratio(fw, bw);
    const double h_split = split_ratio(first(h_spin, "bending", 1, Whirl::forward), first(h_spin, "bending", 1, Whirl::backward));
    INFO("solid: rest " << rest.frequency_hz << ", FW " << fw.frequency_hz << ", BW " << bw.frequency_hz
                        << " Hz; harmonic rest " << f1 << " Hz, split " << h_split << ", solid " << split);
    CHECK(fw.frequency_hz > rest.frequency_hz);
    CHECK(bw.frequency_hz < rest.frequency_hz);
    // Measured: 0.0069797 against 0.0069794 (5e-5). The tolerance, 1 %, is
    // of the order of the two levels' first bending frequencies' difference
    // at rest on this mesh (0.7 %: 16 cells around).
    CHECK(split == Approx(h_split).epsilon(1e-2));
    CHECK(fw.relative_residual < 1e-9);
}

TEST_CASE("At rest the spinning solid level gives the solid run's modes", "[rotation][solid][long]") {
    // A paper core on chucks with spring layers and elastic bearings with
    // frames: every coupling of the solid level beside the spinning cells.
    Scene s = testing::on_elastic_bearings(
        testing::with_chucks(testing::paper_core(0.8, 12, 8), InterfaceKind::spring), 3e8, 4e6, 25.0, 6e7);
    s.model = ModelChoice::solid;
    s.analysis.n_modes = 10;
    const RunReport run = testing::solve_without_chuck_factor(s);
    // With the centrifugal term (a static solve on the bearings, nothing
    // pinned): at speed 0 its Omega^2 drops out, so the modes are the run's.
    const RotatingSolid solid(s, 10, {.centrifugal_stiffening = true});
    CHECK(solid.pinned_rigid_motions().empty());
    const std::vector<RotatingMode> modes = solid.modes_at(0.0);
    REQUIRE(modes.size() == run.modes.modes.size());
    for (size_t i = 0; i < modes.size(); ++i) {
        INFO("mode " << i + 1 << ": " << modes[i].frequency_hz << " Hz, run " << run.modes.modes[i].frequency_hz);
        CHECK(modes[i].frequency_hz == Approx(run.modes.modes[i].frequency_hz).epsilon(1e-8));
        CHECK(modes[i].label.type == run.modes.modes[i].label.type);
        CHECK(modes[i].label.n == run.modes.modes[i].label.n);
        CHECK(modes[i].whirl == Whirl::none);
    }
}

