// The a-priori mesh rule (scene/mesh_rule.hpp, issue 33, 12): the counts of
// a generated mesh from the wanted band, by error laws measured on this
// code's elements (docs/validation/accuracy-by-level.md, "The mesh from the band").
#include "scene/mesh_rule.hpp"

#include "scene/case_file.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/scene.hpp"
#include "scene/scene_description.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace coremodal;

namespace {

// Issue 33's ring: a free steel ring of 0.5 m mean radius, 20 mm wall, 50 mm long.
Scene ring(double band_top_hz) {
    Scene s;
    s.name = "ring";
    s.source_file = "(test)";
    s.core = {0.98, 1.02, 0.05, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850)};
    s.supports.kind = SupportKind::free;
    s.analysis.f_min_hz = 1;
    s.analysis.f_max_hz = band_top_hz;
    apply_mesh_level(s, "default");
    return s;
}

// In-plane ring bending, thin-ring theory (Blevins, Formulas for Natural
// Frequency and Mode Shape, 1979, table 9-1 case 1), for the steel ring above.
double thin_ring_hz(int n) {
    const double radius = 0.5, wall = 0.02;
    return n * (n * n - 1) / std::sqrt(n * n + 1.0) * std::sqrt(210e9 / 7850) * wall / std::sqrt(12.0) /
           (radius * radius) / (2 * M_PI);
}

}  // namespace

TEST_CASE("The band's highest ring wave number is thin-ring theory's below its top", "[mesh][mesh_rule]") {
    // Thin-ring theory: n = 2 at 51.0 Hz, 3 at 144, 4 at 276, 5 at 446, 6 at 654, 7 at 902 Hz.
    for (const int n : {2, 3, 6}) {
        INFO("n = " << n);
        const BandWaves below = band_waves(ring(thin_ring_hz(n) * 1.01));
        CHECK(below.n_max == n);
        CHECK(below.n_max_hz == Approx(thin_ring_hz(n)).epsilon(1e-9));
        CHECK(band_waves(ring(thin_ring_hz(n) * 0.99)).n_max == n - 1);
    }
    CHECK(band_waves(ring(40)).n_max == 1);  // no ring mode below the first
}

TEST_CASE("A ring whose band holds a high n gets more elements around than one whose band does not",
          "[mesh][mesh_rule]") {
    // Below 60 Hz only n = 2: the thin-wall count of `default` (48) already
    // keeps it within 1 % (measured 0.80 %, docs/validation/accuracy-by-level.md).
    const Scene low = ring(60);
    CHECK(low.mesh.n_around == 48);
    CHECK(mesh_rule(low, 0.01).around <= 48);
    // Below 700 Hz n = 6 (654 Hz): at 48 around measured 2.0 % off; the rule
    // asks for 1.55 x the fit's count for 1 %.
    const Scene high = ring(700);
    const MeshRule rule = mesh_rule(high, 0.01);
    CHECK(rule.band.n_max == 6);
    CHECK(high.mesh.n_around == rule.around);
    CHECK(high.mesh.n_around == 68);
    CHECK(expected_around_error(25.0, 6, high.mesh.n_around) < 0.01);
    // The level's own target: fine asks for more, coarse for fewer.
    CHECK(mesh_rule(high, level_target_error(*find_mesh_level("fine"))).around > 68);
    CHECK(mesh_rule(high, level_target_error(*find_mesh_level("coarse"))).around < 68);
}

TEST_CASE("The around law reproduces the measured errors within its stated spread", "[mesh][mesh_rule]") {
    // Solid (hex20, 2 through) against the harmonic level, bench/mesh_rule_errors.py.
    struct Point {
        double slenderness;
        int n, around;
        double measured;
    };
    for (const Point p : {Point{25.0, 2, 48, 0.00801}, Point{25.0, 6, 64, 0.00728}, Point{13.2, 4, 48, 0.00422},
                          Point{3.03, 2, 16, 0.01209}, Point{3.03, 6, 48, 0.00112}}) {
        INFO("R/t " << p.slenderness << ", n " << p.n << ", " << p.around << " around");
        const double ratio = p.measured / expected_around_error(p.slenderness, p.n, p.around);
        CHECK(ratio > 0.8);
        CHECK(ratio < 1.56);  // the safety factor 1.55 covers it
    }
    // Along: the free 76 x 15 mm tube's first bending pair (1.5 half-waves) at
    // 6 along, measured +0.32 %, under the envelope.
    CHECK(expected_along_error(1.5, 6) >= 0.0032);
    CHECK(expected_along_error(1.5, 6) < 2 * 0.0032);
}

TEST_CASE("The shipped cases keep their levels' meshes: the rule raises none of them", "[mesh][mesh_rule]") {
    for (const char* name : {"01-iso-free-free-76x15.toml", "02-clamped-76x15.toml", "03-rest-roll-150x15.8-4320.toml",
                             "07-rotogravure-chucks-150x15.8-4320.toml"}) {
        INFO(name);
        const Scene s = parse_case_file(std::string(COREMODAL_SOURCE_DIR) + "/cases/" + name);
        const MeshLevel& level = *find_mesh_level(s.mesh.level);
        const int around = elements_around(level, s.core.inner_diameter, s.core.outer_diameter);
        CHECK(s.mesh.n_around == around);
        CHECK(s.mesh.n_along == *elements_along(s.core.length, s.core.outer_diameter, around, level.axial_aspect));
        const MeshRule rule = mesh_rule(s, level_target_error(level));
        CHECK(rule.around <= s.mesh.n_around);
        CHECK(rule.along <= s.mesh.n_along);
    }
}

TEST_CASE("Explicit counts win; the rule says what they expect and warns when they are far too coarse",
          "[mesh][mesh_rule]") {
    Scene s = ring(700);
    s.mesh.level = "custom";
    s.mesh.n_around = 16;
    // At the solid level 16 around expects tens of % on n = 6: warned, kept.
    const auto warning = explicit_mesh_warning(s, true);
    REQUIRE(warning);
    CHECK_THAT(*warning,
               Catch::StartsWith("[mesh] is coarser than the band needs (top 700 Hz): around = 16 expects ") &&
                   Catch::Contains("on the band's n = 6 modes (68 for 1 %); kept as given"));
    CHECK(s.mesh.n_around == 16);
    // At the harmonic levels around only draws the modes.
    CHECK_FALSE(explicit_mesh_warning(s, false));
    // The rule's line names the band, n, the counts and this mesh's expected errors.
    const std::string text = *mesh_rule_text(s);
    CHECK_THAT(text, Catch::Contains("top 700 Hz ([analysis] band), highest n = 6 (thin ring/shell 656") &&
                         Catch::Contains("it asks for 68 around (R/t 25)") && Catch::Contains("this mesh (3/16/") &&
                         Catch::Contains("the default level's target"));
    s.mesh.n_around = 68;
    CHECK_FALSE(explicit_mesh_warning(s, true));
}

TEST_CASE("coremodal check says the rule and why a count was raised", "[mesh][mesh_rule][check]") {
    const Scene s = ring(700);
    const std::string text = describe_scene(s, KeySources{});
    INFO(text);
    CHECK_THAT(text, Catch::Contains("[mesh] around = 68") &&
                         Catch::Contains("its 32 raised for the band's n = 6 (docs/validation/accuracy-by-level.md") &&
                         Catch::Contains("[mesh] rule = mesh from the band"));
}
