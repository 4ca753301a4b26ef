// The model level a run uses: "auto" resolves to the harmonic level for a
// body of revolution, to the coupled harmonics when only segmented chucks on
// a spring layer break the symmetry, and to the solid otherwise; a named
// level stays.
#include "models/choose.hpp"

#include "models/beam/beam_level.hpp"
#include "models/coupled/coupled_level.hpp"
#include "models/harmonic/harmonic_level.hpp"
#include "models/solid/solid_level.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

namespace {

Scene with_model(ModelChoice model) {
    Scene s;
    s.model = model;
    return s;
}

}  // namespace

TEST_CASE("auto picks the harmonic level for a body of revolution, else the coupled level or the solid", "[model][choose]") {
    Scene plain = with_model(ModelChoice::automatic);
    CHECK(chosen_level(plain) == ModelChoice::harmonic);
    CHECK(dynamic_cast<HarmonicLevel*>(make_model_level(plain).get()) != nullptr);

    Scene user_mesh = with_model(ModelChoice::automatic);
    user_mesh.mesh.file = "tube.msh";
    CHECK(chosen_level(user_mesh) == ModelChoice::solid);
    CHECK(dynamic_cast<SolidLevel*>(make_model_level(user_mesh).get()) != nullptr);

    Scene segmented = with_model(ModelChoice::automatic);
    ChuckSpec chuck;
    chuck.name = "left";
    ExpandingElement element;
    element.segments = 3;
    chuck.expanding.push_back(element);
    segmented.supports.chucks.push_back(chuck);
    CHECK(chosen_level(segmented) == ModelChoice::coupled);
    CHECK_THAT(*why_not_axisymmetric(segmented), Catch::Contains("3 segments"));
}

TEST_CASE("auto picks the coupled harmonics when only segmented spring-layer chucks or a one-sided contact break the symmetry",
          "[model][choose][coupled]") {
    Scene segmented = with_model(ModelChoice::automatic);
    ChuckSpec chuck;
    chuck.name = "left";
    ExpandingElement element;
    element.segments = 3;
    chuck.expanding.push_back(element);
    segmented.supports.chucks.push_back(chuck);
    CHECK(chosen_level(segmented) == ModelChoice::coupled);
    CHECK(dynamic_cast<CoupledLevel*>(make_model_level(segmented).get()) != nullptr);
    CHECK_THAT(*why_coupled(segmented), Catch::Contains("3 segments") && Catch::Contains("coupled harmonics"));
    CHECK_THAT(level_choice_text(segmented, "the case file"), Catch::StartsWith("coupled (the case file; "));

    SECTION("and a chuck not expanded (one-sided contact), saying why") {
        Scene one_sided = with_model(ModelChoice::automatic);
        ChuckSpec loose;
        loose.name = "left";
        loose.interface.contact = ContactKind::one_sided;
        loose.expanding.push_back(element);  // retracted: its segments do not matter
        one_sided.supports.chucks.push_back(loose);
        CHECK(chosen_level(one_sided) == ModelChoice::coupled);
        CHECK_THAT(*why_coupled(one_sided), Catch::Contains("not expanded") && Catch::Contains("the contact's arc") &&
                                                Catch::Contains("coupled harmonics"));
        CHECK_THAT(level_choice_text(one_sided, "the case file"), Catch::StartsWith("coupled (the case file; "));
    }
    SECTION("but not bonded segments (ties over arcs) or a [mesh] file: the solid") {
        Scene bonded = segmented;
        bonded.supports.chucks[0].interface.kind = InterfaceKind::bonded;
        CHECK(chosen_level(bonded) == ModelChoice::solid);
        Scene one_sided_bonded = bonded;  // a bonded segment beside a one-sided contact: still the solid
        one_sided_bonded.supports.chucks.push_back(bonded.supports.chucks[0]);
        one_sided_bonded.supports.chucks[1].name = "right";
        one_sided_bonded.supports.chucks[1].interface = {};
        one_sided_bonded.supports.chucks[1].interface.contact = ContactKind::one_sided;
        CHECK(chosen_level(one_sided_bonded) == ModelChoice::solid);
        Scene user_mesh = segmented;
        user_mesh.mesh.file = "tube.msh";
        CHECK(chosen_level(user_mesh) == ModelChoice::solid);
    }
    SECTION("and a body of revolution stays at the harmonic level") {
        CHECK(!why_coupled(with_model(ModelChoice::automatic)));
        CHECK(chosen_level(with_model(ModelChoice::automatic)) == ModelChoice::harmonic);
    }
}

TEST_CASE("a named model level is kept, and each has its own step count", "[model][choose]") {
    for (const ModelChoice level : {ModelChoice::solid, ModelChoice::harmonic, ModelChoice::coupled, ModelChoice::beam})
        CHECK(chosen_level(with_model(level)) == level);
    CHECK(make_model_level(with_model(ModelChoice::beam))->steps() == 4);
    CHECK(make_model_level(with_model(ModelChoice::solid))->steps() == 7);
    CHECK(dynamic_cast<BeamLevel*>(make_model_level(with_model(ModelChoice::beam)).get()) != nullptr);
}
