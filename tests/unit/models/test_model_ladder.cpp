// Each level hands out its converge ladder (ModelLevel::converge_ladder,
// models/ladder/model_ladder.hpp): the solid's k = first ... first +
// levels - 1, the harmonic level's the same section two levels finer, the
// beam's five doublings; a level without one refuses, a scene a level
// cannot solve leaves a note instead of a ladder. Built without running a
// meshed step (the beam's ladder runs its coarsest step once, ~1 ms).
#include "models/choose.hpp"
#include "models/ladder/model_ladder.hpp"

#include "common/error.hpp"
#include "scene/case_file.hpp"

#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <vector>

using namespace coremodal;

TEST_CASE("Each level hands out its converge ladder; a level without one refuses", "[converge][models]") {
    const Scene scene = parse_case_text(testing::kClampedTesterCore, "ladder.toml");
    LadderRequest request;
    request.first = 1, request.levels = 3, request.n_modes = 6;
    request.modes_given = true;
    std::vector<std::string> notes;
    const auto ladder = [&](ModelChoice level) { return make_model_level(level)->converge_ladder(scene, request, notes); };

    const std::optional<ModelLadder> solid = ladder(ModelChoice::solid);
    REQUIRE(solid);
    CHECK(solid->model == ModelChoice::solid);
    REQUIRE(solid->steps.size() == 3);
    CHECK(solid->steps.back().k == 3);
    CHECK(solid->refined_dimensions == 3);

    // The same unit, kHarmonicExtraLevels finer: level k meshes the solid's level k's section.
    const std::optional<ModelLadder> harmonic = ladder(ModelChoice::harmonic);
    REQUIRE(harmonic);
    REQUIRE(harmonic->steps.size() == 3 + kHarmonicExtraLevels);
    for (size_t i = 0; i < solid->steps.size(); ++i) CHECK(harmonic->steps[i].counts == solid->steps[i].counts);
    CHECK(harmonic->refined_dimensions == 2);

    // h = 1/k with k = 1, 2, 4, ...; the modes as given (modes_given), the runs repeated.
    const std::optional<ModelLadder> beam = ladder(ModelChoice::beam);
    REQUIRE(beam);
    REQUIRE(beam->steps.size() == kBeamLevels);
    CHECK(beam->steps[1].k == 2 * beam->steps[0].k);
    CHECK(beam->n_modes == 6);
    CHECK(beam->runs_per_level == kBeamRunsPerLevel);
    CHECK(beam->unseen_roles.size() == 2);
    CHECK(notes.empty());

    CHECK_THROWS_AS(ladder(ModelChoice::coupled), InputError);
}

TEST_CASE("A scene the harmonic level cannot solve leaves a note, not a ladder", "[converge][models]") {
    // A user's mesh has no r-z section to revolve (models/choose.cpp, why_not_axisymmetric).
    Scene scene = parse_case_text(testing::kClampedTesterCore, "ladder.toml");
    scene.mesh.file = "roll.msh";
    std::vector<std::string> notes;
    CHECK_FALSE(make_model_level(ModelChoice::harmonic)->converge_ladder(scene, LadderRequest{}, notes));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0] == "harmonic model level skipped: a [mesh] file: the harmonic level meshes the scene's own r-z section");
}
