// The coupled-harmonic level (models/coupled, docs/harmonic.md "Coupled
// harmonics"): with nothing to couple it is the harmonic level; with
// segmented chucks it agrees with the 3D solid within the solid's own
// circumferential error; and it converges in N from above.
#include "tube_scenes.hpp"

#include "geometry/section_mesh.hpp"
#include "geometry/tube_section.hpp"
#include "models/coupled/coupled_level.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

// The paper core of the chuck tests (1 m, 76 x 15 mm) on spring-layer chucks,
// each band cut into `segments` pads of `angle_deg` (0: full bands).
Scene segmented_chucks(int segments, double angle_deg, int around = 16, int along = 24) {
    Scene s = with_chucks(paper_core(1.0, around, along), InterfaceKind::spring);
    for (ChuckSpec& c : s.supports.chucks)
        for (ExpandingElement& e : c.expanding) {
            e.segments = segments;
            e.segment_angle = angle_deg * M_PI / 180;
        }
    s.analysis.n_modes = 10;
    return s;
}

Scene at_level(Scene s, const std::string& level) {
    s.model = level;
    return s;
}

CoupledModes coupled_at(const Scene& scene, int n_max) {
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    const std::vector<PartMaterial> materials = part_materials(scene, section.part_names, "generated section");
    return solve_coupled(scene, section, materials, n_max, solve_request(scene));
}

}  // namespace

TEST_CASE("Coupled level with full bands: block diagonal, the harmonic level's eigenvalues to 1e-8", "[coupled]") {
    const Scene scene = segmented_chucks(0, 0);
    const RunReport h = solve_without_chuck_factor(at_level(scene, "harmonic"));
    const CoupledModes c = coupled_at(scene, 4);
    CHECK(c.n_coupling_entries == 0);
    REQUIRE(c.verification.complete);
    REQUIRE(c.eigenvalues.size() >= h.modes.modes.size());
    for (size_t i = 0; i < h.modes.modes.size(); ++i) {
        const Mode& m = h.modes.modes[i];
        INFO("mode " << i + 1 << ": " << m.label.type << " n=" << m.label.n << " " << m.frequency_hz << " Hz");
        REQUIRE(m.label.n <= 4);
        CHECK(c.eigenvalues[i] == Approx(m.eigenvalue).epsilon(1e-8));
    }
    CHECK(c.mass_kg == Approx(h.model.mass_kg).epsilon(1e-12));
    SECTION("and a level asked for coupled harmonics of a scene nothing couples hands it to the harmonic level") {
        const RunReport r = solve_without_chuck_factor(at_level(scene, "coupled"));
        REQUIRE(r.modes.modes.size() == h.modes.modes.size());
        for (size_t i = 0; i < r.modes.modes.size(); ++i)
            CHECK(r.modes.modes[i].eigenvalue == Approx(h.modes.modes[i].eigenvalue).epsilon(1e-12));
    }
}

TEST_CASE("Coupled level: pads that cover the whole circumference are the full band", "[coupled]") {
    // One segment of 360 deg: I_pads = I_band for every pair, so no coupling survives.
    const CoupledModes one = coupled_at(segmented_chucks(1, 360), 3);
    const CoupledModes band = coupled_at(segmented_chucks(0, 0), 3);
    CHECK(one.n_coupling_entries == 0);
    REQUIRE(one.eigenvalues.size() >= 8);
    for (size_t i = 0; i < 8; ++i) CHECK(one.eigenvalues[i] == Approx(band.eigenvalues[i]).epsilon(1e-10));
}

TEST_CASE("Coupled level converges in N from above, in shrinking steps", "[coupled]") {
    const Scene scene = segmented_chucks(3, 60);
    std::vector<std::vector<double>> lambdas;
    for (int n_max : {4, 7, 10, 13}) {
        const CoupledModes c = coupled_at(scene, n_max);
        REQUIRE(c.verification.complete);
        CHECK(c.n_coupling_entries > 0);
        lambdas.push_back({c.eigenvalues.begin(), c.eigenvalues.begin() + 10});
    }
    std::vector<double> step(lambdas.size(), 0);
    for (size_t s = 1; s < lambdas.size(); ++s)
        for (size_t i = 0; i < 10; ++i) {
            // Nested spaces (Rayleigh-Ritz): no eigenvalue rises when harmonics are added.
            CHECK(lambdas[s][i] <= lambdas[s - 1][i] * (1 + 1e-10));
            step[s] = std::max(step[s], (lambdas[s - 1][i] - lambdas[s][i]) / lambdas[s][i]);
        }
    INFO("largest relative eigenvalue steps: " << step[1] << ", " << step[2] << ", " << step[3]);
    CHECK(step[1] > 0);
    CHECK(step[2] < step[1]);
    CHECK(step[3] < step[2]);
    CHECK(step[3] < step[1] / 4);  // measured: 0.0139, 0.0039, 0.0017 (eigenvalues, twice the frequency change)
}

TEST_CASE("Coupled level against the 3D solid on segmented chucks, mode by mode", "[coupled][long]") {
    const Scene scene = segmented_chucks(3, 60);
    const RunReport c = solve_without_chuck_factor(at_level(scene, "coupled"));
    REQUIRE(c.model.level == "coupled");
    REQUIRE(c.modes.verification.complete);
    CHECK(c.modes.verification.max_relative_residual < 1e-8);
    CHECK(c.modes.verification.max_orthonormality_error < 1e-8);
    CHECK(c.model.mass_kg == Approx(c.model.expected_mass_kg).epsilon(1e-9));
    const RunReport coarse = solve_without_chuck_factor(at_level(segmented_chucks(3, 60, 16), "solid"));
    const RunReport fine = solve_without_chuck_factor(at_level(segmented_chucks(3, 60, 32), "solid"));
    REQUIRE(fine.modes.modes.size() == c.modes.modes.size());
    for (size_t i = 0; i < c.modes.modes.size(); ++i) {
        const Mode &a = c.modes.modes[i], &b = fine.modes.modes[i], &b16 = coarse.modes.modes[i];
        INFO("mode " << i + 1 << ": coupled " << a.frequency_hz << " Hz " << a.label.type << " n=" << a.label.n
                     << ", solid 32 around " << b.frequency_hz << " Hz " << b.label.type << " n=" << b.label.n
                     << ", 16 around " << b16.frequency_hz << " Hz");
        CHECK(a.label.type == b.label.type);
        CHECK(a.label.n == b.label.n);
        // The solid at 32 around is off the converged value by less than its
        // change from 16 to 32 around whenever it converges at least at first
        // order in theta; 2e-4 more covers its quadratic arcs (mass 1e-5 low)
        // and the coupled truncation (kCoupledTolerance).
        const double solid_error = std::abs(b16.frequency_hz - b.frequency_hz);
        CHECK(std::abs(a.frequency_hz - b.frequency_hz) <= solid_error + 2e-4 * b.frequency_hz);
    }
}
