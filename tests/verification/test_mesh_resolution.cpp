// Meshes that do not lie (issue 33, items 11 and 12): thin walls mesh at the
// solid level with every cell the right way out, and a solid mesh that does
// not resolve its modes around says so and by how much.
#include "tube_scenes.hpp"

#include "common/format.hpp"
#include "element/element.hpp"
#include "models/solid/mesh_resolution.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/mesh_rule.hpp"

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

TEST_CASE("The mesh check matches a solid mode with the harmonic one of its label just below it",
          "[mesh][mesh_resolution]") {
    // A 0.5 m ring of 20 mm wall at 16 around (issue 33): its n = 2 ovalling
    // pair at 74.127 Hz locks 45 % above the harmonic level's 50.98 Hz, and
    // the harmonic level's next n = 2, m = 0 mode (92.333 Hz) is nearer in
    // frequency; matched with that one the check reported -19.7 %.
    const auto mode = [](int index, double hz, const char* type, int n, int m) {
        Mode x;
        x.index = index;
        x.frequency_hz = hz;
        x.label = {type, n, m, 1.0};
        return x;
    };
    const std::vector<Mode> harmonic = {mode(1, 0, "rigid", 0, 0), mode(7, 50.98, "ovalling", 2, 0),
                                        mode(8, 50.98, "ovalling", 2, 0), mode(9, 92.333, "ovalling", 2, 0),
                                        mode(11, 140.0, "ovalling", 3, 0)};
    const std::vector<Mode> solid = {mode(1, 0, "rigid", 0, 0), mode(7, 74.127, "ovalling", 2, 0),
                                     mode(8, 74.127, "ovalling", 2, 0), mode(9, 92.340, "ovalling", 2, 0),
                                     mode(10, 95.0, "support", 1, 0), mode(11, 139.9999, "ovalling", 3, 0)};
    const MeshResolution r = compare_with_harmonic(solid, harmonic);
    CHECK(r.compared == 4);  // the rigid and the support mode are not compared
    CHECK(r.mode_index == 7);
    CHECK(r.harmonic_hz == 50.98);
    CHECK(r.error() == Approx(74.127 / 50.98 - 1).epsilon(1e-12));  // +45 %
    // A mode a hair below its counterpart (the arcs are quadratic, not the
    // circle) is still matched with it, not with a lower one: n = 3 compares
    // 139.9999 with 140.0, not with nothing.
    const MeshResolution only_n3 = compare_with_harmonic({solid.back()}, harmonic);
    CHECK(only_n3.compared == 1);
    CHECK(only_n3.harmonic_hz == 140.0);
}

TEST_CASE("A solid run whose mesh does not resolve its ovalling says so, by how much and what would",
          "[verification][mesh][mesh_resolution]") {
    // Issue 33's ring: 0.5 m mean radius, 20 mm wall, steel, free; 50 mm long.
    // The harmonic level (exact around) against thin-ring theory: 50.98 Hz
    // against 51.0 Hz (the ring is 1/25 as thick as its radius).
    const double mean_radius = 0.5, wall = 0.02;
    Scene ring = steel_tube(2 * mean_radius + wall, 2 * mean_radius - wall, 0.05, 2, 16, 8, 10);
    Scene harmonic = ring;
    harmonic.model = ModelChoice::harmonic;
    const RunReport h = solve_quietly(harmonic);
    const Mode& oval = nth_of_type(h, "ovalling");
    CHECK(oval.label.n == 2);
    CHECK(oval.frequency_hz == Approx(thin_ring_hz(2, mean_radius, wall)).epsilon(0.005));
    CHECK(h.warnings.empty());

    // 16 around (c = 16 / (2 pi sqrt(R / t)) = 0.51): the solid's n = 2 pair
    // locks 45 % high (docs/validation/accuracy-by-level.md, "Thin walls"); the run warns,
    // names the mode, both frequencies, and the level whose count fixes it
    // (coarse: 40 around for the band's n = 3 by the rule, scene/mesh_rule.hpp;
    // n = 2 then 3.7 % x (32 / 40)^3.7 = 1.6 % by the measured law).
    const RunReport coarse = solve_quietly(ring);
    const Mode& locked = nth_of_type(coarse, "ovalling");
    CHECK(locked.frequency_hz / oval.frequency_hz - 1 > 0.4);
    // The a-priori rule warned first (scene/mesh_rule.hpp), at meshing; the
    // check against the harmonic level after the solve.
    REQUIRE(coarse.warnings.size() == 2);
    CHECK_THAT(coarse.warnings[0], Catch::StartsWith("[mesh] is coarser than the band needs") &&
                                       Catch::Contains("around = 16 expects "));
    const std::string all = coarse.warnings[1];
    INFO(all);
    // Either member of the pair may be named; the error is the pair's.
    const std::string percent = significant(100 * (locked.frequency_hz / oval.frequency_hz - 1), 3) + " % off";
    CHECK_THAT(all, Catch::StartsWith("GROSSLY UNRESOLVED: the mesh (custom, 16 elements around) does not resolve "
                                      "mode ") &&
                        Catch::Contains(" (ovalling n=2 m=0): ") && Catch::Contains(percent) &&
                        Catch::Contains("expected --mesh coarse or finer"));

    // 48 around (c = 1.53, the default level's count for this wall): within
    // the 2 % the check allows, and no warning.
    ring.mesh.n_around = 48;
    const RunReport resolved = solve_quietly(ring);
    CHECK(nth_of_type(resolved, "ovalling").frequency_hz == Approx(oval.frequency_hz).epsilon(0.02));
    CHECK(resolved.warnings.empty());
}

TEST_CASE("The rule's mesh resolves the band's highest n within its target at the solid level",
          "[verification][mesh][mesh_rule][long]") {
    // Issue 33's ring with a band to 700 Hz: thin-ring theory puts n = 6 at
    // 656 Hz inside it. `default` asks for 68 around (scene/mesh_rule.hpp);
    // the thin-wall count alone (48) leaves n = 6 2.0 % stiff (measured,
    // docs/validation/accuracy-by-level.md). Along and through do not matter for these
    // m = 0 modes (2 along, 2 through: within 0.01 %, the "through" table).
    const double mean_radius = 0.5, wall = 0.02;
    Scene ring = steel_tube(2 * mean_radius + wall, 2 * mean_radius - wall, 0.05, 2, 16, 2, 10);
    ring.analysis.f_min_hz = 1;
    ring.analysis.f_max_hz = 700;
    Scene with_level = ring;
    apply_mesh_level(with_level, "default");
    REQUIRE(with_level.mesh.n_around == 68);
    const auto ovalling_hz = [](const RunReport& r, int n) {
        for (const Mode& m : r.modes.modes)
            if (m.label.type == "ovalling" && m.label.n == n && m.label.m == 0) return m.frequency_hz;
        return 0.0;
    };
    Scene harmonic = ring;
    harmonic.model = ModelChoice::harmonic;
    const double exact = ovalling_hz(solve_quietly(harmonic), 6);
    REQUIRE(exact == Approx(thin_ring_hz(6, mean_radius, wall)).epsilon(0.01));
    for (const int around : {48, 68}) {
        INFO(around << " around");
        ring.mesh.n_around = around;
        const double error = ovalling_hz(solve_quietly(ring), 6) / exact - 1;
        if (around == 68) {
            CHECK(error > 0);
            CHECK(error < 0.01);  // the default level's target
        } else {
            CHECK(error > 0.015);  // the thin-wall count alone: not within it
        }
    }
}
