// Meshes that do not lie (issue 33, items 11 and 12): thin walls mesh at the
// solid level with every cell the right way out, and a solid mesh that does
// not resolve its modes around says so and by how much.
#include "tube_scenes.hpp"

#include "element/element.hpp"
#include "models/solid/mesh_resolution.hpp"
#include "scene/mesh_levels.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

// A steel tube at a named mesh level.
Scene steel_at_level(double d_in, double wall, double length, const char* level, int n_modes) {
    Scene s = steel_tube(d_in + 2 * wall, d_in, length, 2, 16, 8, n_modes);
    apply_mesh_level(s, level);
    return s;
}

// The volume of the generated mesh; element_volume throws on a cell whose
// Jacobian determinant is not positive at an integration point.
double checked_volume(const Mesh& mesh) {
    double v = 0;
    CellCoords x(mesh.nodes_per_cell(), 3);
    for (int c = 0; c < mesh.n_cells(); ++c) {
        for (int a = 0; a < mesh.nodes_per_cell(); ++a)
            for (int k = 0; k < 3; ++k) x(a, k) = mesh.nodes[mesh.cell(c)[a]][k];
        v += element_volume(mesh.cell_type, x);
    }
    return v;
}

// Area inside n quadratic arcs through points of a circle of radius r (the
// exact area of the cells' edges, tests/unit/mesh/test_gmsh_mesh.cpp).
double quadratic_polygon_area(double r, int n) {
    const double a = M_PI / n;
    return n * r * r * std::sin(a) * (std::cos(a) + 4.0 / 3.0 * (1 - std::cos(a)));
}

// In-plane ring bending, thin-ring theory (Blevins, Formulas for Natural
// Frequency and Mode Shape, 1979, table 9-1 case 1; Soedel, Vibrations of
// Shells and Plates, 3rd ed. 2004, eq. 2.7.13): f_n = n (n^2 - 1) /
// sqrt(n^2 + 1) sqrt(E I / (rho A R^4)) / (2 pi), R the mean radius, I / A
// = t^2 / 12.
double thin_ring_hz(int n, double mean_radius, double wall) {
    const double c = std::sqrt(210e9 / 7850);
    return n * (n * n - 1) / std::sqrt(n * n + 1.0) * c * wall / std::sqrt(12.0) /
           (mean_radius * mean_radius) / (2 * M_PI);
}

}  // namespace

TEST_CASE("Thin walls mesh at the solid level: every cell the right way out, the volume of the wall",
          "[verification][mesh][thin_wall]") {
    // Issue 33: a 76 mm core with a 1 mm wall failed on the coarse mesh, a
    // 0.5 mm wall on the default one, and a 0.5 m ring with a 5 mm wall on
    // both ("hex20 cell: Jacobian determinant ... <= 0"): gmsh put the
    // midside node of an edge inside the wall on the arc's chord, the sagitta
    // r (1 - cos(pi / n_around)) inside its arc.
    struct Wall {
        double d_in, wall;
    };
    for (const Wall w : {Wall{0.076, 1e-3}, Wall{0.076, 0.5e-3}, Wall{0.990, 5e-3}})
        for (const char* level : {"coarse", "default"}) {
            INFO("bore " << w.d_in << " m, wall " << w.wall << " m, " << level);
            const Scene s = steel_at_level(w.d_in, w.wall, 0.2, level, 8);
            const Mesh mesh = generated_mesh(s);
            double volume = 0;
            REQUIRE_NOTHROW(volume = checked_volume(mesh));
            const double ri = w.d_in / 2, ro = ri + w.wall;
            const double exact = (quadratic_polygon_area(ro, s.mesh.n_around) -
                                  quadratic_polygon_area(ri, s.mesh.n_around)) * s.core.length;
            CHECK(volume == Approx(exact).epsilon(1e-9));
        }
}

TEST_CASE("A thin wall's ovalling at the solid level is within a few per cent of the harmonic level",
          "[verification][mesh][thin_wall]") {
    // A 76 mm paper core with a 0.5 mm wall, 0.1 m long, free: its lowest
    // elastic modes are the n = 2 ovalling pair. Before issue 33 the coarse
    // and default meshes failed (inverted cells); with the midside nodes on
    // their arcs alone, 16 and 32 around locked (+176 % and +24 %). The
    // levels now put at least c 2 pi sqrt(R / t) elements around (c = 1 at
    // coarse, 1.5 at default; scene/mesh_levels.hpp). Measured on a 0.5 m
    // core: +3.0 % (coarse), +0.55 % (default).
    struct Expect {
        const char* level;
        double tolerance;
    };
    for (const Expect e : {Expect{"coarse", 0.04}, Expect{"default", 0.01}}) {
        Scene s = steel_at_level(0.076, 0.5e-3, 0.1, e.level, 10);
        s.core.material = paperboard();
        const RunReport solid = solve_without_chuck_factor(s);
        const RunReport harmonic = solve_without_chuck_factor(at_level(s, "harmonic"));
        const double f_solid = nth_of_type(solid, "ovalling").frequency_hz;
        const double f_harmonic = nth_of_type(harmonic, "ovalling").frequency_hz;
        INFO(e.level << ": " << s.mesh.n_around << " around, solid " << f_solid << " Hz, harmonic " << f_harmonic
                     << " Hz");
        CHECK(f_solid >= f_harmonic * (1 - 1e-4));  // the elements around stiffen it
        CHECK(f_solid <= f_harmonic * (1 + e.tolerance));
    }
}

TEST_CASE("A ring meshed too coarsely around says so, by how much, and which level resolves it",
          "[verification][mesh][resolution]") {
    // Issue 33: a steel ring of 0.5 m radius with a 20 mm wall gave its n = 2
    // in-plane mode at 130.45 Hz on the coarse mesh (16 around), with no word;
    // thin-ring theory gives 51.0 Hz. Here on 16 around (as the coarse level
    // was) and on today's coarse level (32 around for this wall).
    const double d_in = 0.98, wall = 0.02, mean_radius = (d_in + wall) / 2;
    Scene s = steel_at_level(d_in, wall, 0.05, "coarse", 12);
    REQUIRE(s.mesh.n_around == 32);  // 2 pi sqrt(R / t) = 31.3 elements at c = 1
    const RunReport h = solve_without_chuck_factor(at_level(s, "harmonic"));
    // The harmonic level is exact around; it agrees with thin-ring theory to
    // the shear and rotary inertia of a wall t / R = 0.04 thick (0.1 %).
    CHECK(nth_of_type(h, "ovalling").frequency_hz == Approx(thin_ring_hz(2, mean_radius, wall)).epsilon(3e-3));
    for (int around : {16, 32}) {
        s.mesh.n_around = around;
        const RunReport solid = solve_without_chuck_factor(s);
        const MeshResolution r = compare_with_harmonic(solid.modes.modes, h.modes.modes);
        REQUIRE(r.compared > 0);
        // The estimate against the truth: the worst mode's frequency over
        // thin-ring theory's for its n (n = 2 or 3, the ovalling pairs here).
        const Mode& worst = solid.modes.modes.at(r.mode_index - 1);
        REQUIRE(worst.label.type == "ovalling");
        const double truth = worst.frequency_hz / thin_ring_hz(worst.label.n, mean_radius, wall) - 1;
        INFO(around << " around: " << r.label << " " << r.solid_hz << " Hz against " << r.harmonic_hz
                    << " Hz, estimate " << r.error() << ", against theory " << truth);
        // Thin-ring theory is itself off by the wall's shear and rotary
        // inertia (t / R = 0.04: 0.06 % at n = 2, 0.17 % at n = 3 against the
        // harmonic level), times 1 + e: 0.27 % measured at 16 around.
        CHECK(r.error() == Approx(truth).margin(5e-3));
        if (around == 16) {
            // The run said so, and what to use: +46 % (n = 2) to +52 % (n = 3)
            // is gross; by the (n_around)^-3.5 law the default level's 48
            // around leave 1.1 %, the fine level's 64 0.4 %.
            CHECK(r.error() > 0.40);
            REQUIRE(solid.warnings.size() == 1);
            const std::string& warning = solid.warnings.front();
            CHECK_THAT(warning, Catch::Matchers::Contains("does not resolve mode " + std::to_string(r.mode_index)));
            CHECK_THAT(warning, Catch::Matchers::Contains("GROSSLY UNRESOLVED"));
            CHECK_THAT(warning, Catch::Matchers::Contains("expected --mesh fine or finer"));
        } else {
            // Today's coarse level: +3.7 % (n = 2), +4.5 % (n = 3), within
            // what the coarse level promises for ovalling: no warning.
            CHECK(r.error() > 0.02);
            CHECK(r.error() < kMeshWarnError);
            CHECK(solid.warnings.empty());
        }
    }
}
