// The refinement ladders of converge (models/ladder/refinement_ladder.hpp):
// every direction and axial segment refined by k, the unit and its bound on
// the DOFs, and the beam ladder; bad input refused with what is expected.
#include "models/ladder/refinement_ladder.hpp"

#include "common/error.hpp"
#include "geometry/tube_section.hpp"
#include "scene/case_file.hpp"

#include "support/converge_levels.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace coremodal;
using coremodal::testing::case_path;

TEST_CASE("The ladder refines every direction and every axial segment by k", "[converge]") {
    const Scene scene = parse_case_file(case_path("03-rest-roll-150x15.8-4320.toml"));
    const UnitMesh unit = parse_unit("1/1/8/11", "--unit");
    const auto steps = refinement_ladder(scene, unit, 1, 4);
    REQUIRE(steps.size() == 4);
    const auto& unit_segments = steps[0].mesh.along_per_segment;
    REQUIRE(unit_segments.size() == 5);  // end, clamp, free span, clamp, end
    for (const auto& s : steps) {
        CAPTURE(s.label);
        CHECK(s.h == Approx(1.0 / s.k));
        CHECK(s.mesh.n_wall == s.k);
        CHECK(s.mesh.n_rest_paper == s.k);
        CHECK(s.mesh.n_around == 8 * s.k);
        for (std::size_t i = 0; i < unit_segments.size(); ++i)
            CHECK(s.mesh.along_per_segment[i] == s.k * unit_segments[i]);
        // The mesher takes the counts as given.
        Scene refined = scene;
        refined.mesh = s.mesh;
        const TubeSection section = make_tube_section(refined);
        for (std::size_t i = 0; i < section.segments.size(); ++i)
            CHECK(section.segments[i].n_elements == s.mesh.along_per_segment[i]);
    }
    CHECK(steps[3].label == "k=4 4/4/32/" + std::to_string(steps[3].mesh.n_along));

    SECTION("The default unit keeps the case's axial element aspect") {
        const UnitMesh d = default_unit(scene);
        CHECK(d.n_wall == 1);
        CHECK(d.n_around == kUnitElementsAround);
        CHECK(d.n_along == (scene.mesh.n_along * 8 + scene.mesh.n_around - 1) / scene.mesh.n_around);
    }
}

TEST_CASE("Bad ladder input is refused with the option and what is expected", "[converge]") {
    CHECK_THROWS_WITH(parse_unit("1/1/8", "--unit"), Catch::Contains("--unit 1/1/8: 3 counts"));
    CHECK_THROWS_WITH(parse_unit("1/x/8/10", "--unit"), Catch::Contains("'x' is not a positive whole number"));
    CHECK_THROWS_WITH(parse_unit("1/1/10/10", "--unit"), Catch::Contains("multiple of 4"));
    CHECK_THROWS_WITH(parse_unit("1/0/8/10", "--unit"), Catch::Contains("expected WALL/PAPER/AROUND/ALONG"));
    const Scene free_core = parse_case_file(case_path("01-iso-free-free-76x15.toml"));
    CHECK_THROWS_WITH(refinement_ladder(free_core, UnitMesh{1, 1, 8, 10}, 1, 2), Catch::Contains("at least 3"));
    const Scene user_mesh = parse_case_file(case_path("04-user-mesh-76x15.toml"));
    CHECK_THROWS_AS(refinement_ladder(user_mesh, UnitMesh{1, 1, 8, 10}, 1, 4), InputError);
    CHECK_THROWS_WITH(refinement_ladder(user_mesh, UnitMesh{1, 1, 8, 10}, 1, 4),
                      Catch::Contains("converge refines the generated mesh"));
}

TEST_CASE("The DOF estimate of a tube mesh and the study's cost bound", "[converge]") {
    const Scene rest_roll = parse_case_file(case_path("03-rest-roll-150x15.8-4320.toml"));
    MeshSpec m = rest_roll.mesh;
    m.n_wall = 4, m.n_rest_paper = 4, m.n_around = 32, m.n_along = 104;
    // Measured: 346,944 DOFs after eliminating the clamped nodes (docs/validation/accuracy-vs-cost.md).
    CHECK(estimate_dofs(m, true) == 351936);
    CHECK(estimate_dofs(m, true) > 346944);
    CHECK(estimate_dofs(m, true) < 1.02 * 346944);
    CHECK(mesh_counts_text(m, true) == "4/4/32/104");
    CHECK(mesh_counts_text(m, false) == "4/-/32/104");

    SECTION("A chuck scene counts its chuck bodies and shafts") {
        // Measured: case 07 at the default level has 247,788 DOFs (the two
        // frame masses' nodes, 6 DOFs, are not in the estimate).
        const Scene chucks = parse_case_file(case_path("07-rotogravure-chucks-150x15.8-4320.toml"));
        CHECK(estimate_dofs(chucks, chucks.mesh) == 247788 - 6);
    }
    SECTION("A long rest roll's unit is shortened along until the finest level fits") {
        std::string note;
        const UnitMesh unit = fit_unit_to_budget(rest_roll, default_unit(rest_roll), 1, 4, 200000, note);
        CHECK(unit.n_along < default_unit(rest_roll).n_along);
        CHECK(estimate_dofs(refinement_ladder(rest_roll, unit, 1, 4).back().mesh, true) <= 200000);
        CHECK_THAT(note, Catch::Contains("lowered from 21 to"));
    }
    SECTION("A scene that fits keeps its unit; no bound keeps every unit") {
        const Scene free_core = parse_case_file(case_path("01-iso-free-free-76x15.toml"));
        std::string note;
        CHECK(fit_unit_to_budget(free_core, default_unit(free_core), 1, 4, 200000, note).n_along ==
              default_unit(free_core).n_along);
        CHECK(note.empty());
        CHECK(fit_unit_to_budget(rest_roll, default_unit(rest_roll), 1, 4, 0, note).n_along == 21);
    }
    SECTION("A bound that cannot be met says so") {
        std::string note;
        fit_unit_to_budget(rest_roll, default_unit(rest_roll), 1, 4, 1000, note);
        CHECK_THAT(note, Catch::Contains("exceeds --max-dofs 1000"));
    }
}

TEST_CASE("The beam ladder doubles the elements in every gap between support edges", "[converge][beam]") {
    const Scene scene = parse_case_file(case_path("03-rest-roll-150x15.8-4320.toml"));
    const auto steps = beam_refinement_ladder(scene, kBeamUnitElements, kBeamLevels);
    REQUIRE(steps.size() == static_cast<std::size_t>(kBeamLevels));
    REQUIRE(kBeamLevels >= 4);
    // Unit: 4 elements along the core; the gaps (overhang, clamp zone, free
    // span, clamp zone, overhang) get max(2, round(4 gap / Lc)) = 2, 2, 3, 2, 2.
    CHECK(steps[0].counts == "11/11");
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const int k = 1 << i;
        CAPTURE(steps[i].label);
        CHECK(steps[i].k == k);
        CHECK(steps[i].h == Approx(1.0 / k));
        CHECK(steps[i].counts == std::to_string(11 * k) + "/" + std::to_string(11 * k));
        CHECK(steps[i].label == "k=" + std::to_string(k) + " " + steps[i].counts);
    }
    // Chucks: the chuck beams (body on the core's stations, shaft) refine too.
    const Scene chucked = parse_case_file(case_path("07-rotogravure-chucks-150x15.8-4320.toml"));
    const auto chuck_steps = beam_refinement_ladder(chucked, kBeamUnitElements, 3);
    const auto elements = [](const MeshStep& s) { return std::stoi(s.counts.substr(s.counts.find('/') + 1)); };
    CHECK(elements(chuck_steps[1]) == 2 * elements(chuck_steps[0]));
    CHECK(elements(chuck_steps[2]) == 4 * elements(chuck_steps[0]));
    CHECK_THROWS_WITH(beam_refinement_ladder(scene, kBeamUnitElements, 2), Catch::Contains("at least 3"));
}
