// The model levels' one vocabulary (scene/model_choice.hpp) and their table
// of what each can do (scene/level_traits.hpp): the words are the case
// file's (docs/case-keys: model = "solid" | "harmonic" | "coupled" | "auto" |
// "beam") and summary.json's, and the table says what docs/theory/rotation.md,
// docs/theory/response.md and docs/theory/coupled.md say each level carries.
#include "scene/level_traits.hpp"

#include "common/error.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

using namespace coremodal;

TEST_CASE("Each model level's word reads back to it, in the order the messages list them", "[scene][levels]") {
    const std::vector<std::string_view> words{"solid", "harmonic", "coupled", "auto", "beam"};
    CHECK(model_choice_words() == words);
    for (std::string_view w : words) CHECK(to_string(*parse_model_choice(w)) == w);
    CHECK(parse_model_choice("auto") == ModelChoice::automatic);
    CHECK_FALSE(parse_model_choice("solid3d"));  // the 3D solid is "solid" in every file and message
    CHECK_FALSE(parse_model_choice("Beam"));
    CHECK(model_option("coupled") == ModelChoice::coupled);
    CHECK_THROWS_AS(model_option("shell"), InputError);
    CHECK_THROWS_WITH(model_option("shell"),
                      "--model shell: unknown model level; expected one of solid, harmonic, coupled, auto, beam");
}

TEST_CASE("summary.json writes a model level as its word, not the enum's number", "[scene][levels]") {
    const nlohmann::json j = {{"level", ModelChoice::harmonic}};
    CHECK(j.dump() == R"({"level":"harmonic"})");
}

TEST_CASE("The level table says what each level carries", "[scene][levels]") {
    // Spinning: beam, harmonic and solid have gyroscopic terms; the coupled harmonics not yet (docs/theory/coupled.md).
    CHECK(level_traits(ModelChoice::beam).spins);
    CHECK(level_traits(ModelChoice::harmonic).spins);
    CHECK(level_traits(ModelChoice::solid).spins);
    CHECK_FALSE(level_traits(ModelChoice::coupled).spins);
    CHECK(std::string(level_traits(ModelChoice::coupled).why_not_spinning) ==
          "the coupled harmonics have no spinning terms yet");
    // Centrifugal stiffening needs a continuum's prestress: not in the beam network (effects/rotation.hpp).
    CHECK_FALSE(level_traits(ModelChoice::beam).centrifugal);
    CHECK(level_traits(ModelChoice::harmonic).centrifugal);
    CHECK(level_traits(ModelChoice::solid).centrifugal);
    // Sensitivities from the assembled operators: the beam and the harmonic level.
    CHECK(level_traits(ModelChoice::beam).sensitivities);
    CHECK(level_traits(ModelChoice::harmonic).sensitivities);
    CHECK_FALSE(level_traits(ModelChoice::solid).sensitivities);
    CHECK_FALSE(level_traits(ModelChoice::coupled).sensitivities);
    // Exactly one converge reference, the solid, which every other ladder is measured against.
    int references = 0;
    for (ModelChoice level : {ModelChoice::beam, ModelChoice::harmonic, ModelChoice::coupled, ModelChoice::solid}) {
        CHECK(level_traits(level).level == level);
        references += level_traits(level).converge_reference;
    }
    CHECK(references == 1);
    CHECK(level_traits(ModelChoice::solid).converge_reference);
    // "auto" is no level: chosen_level resolves it before anything asks.
    CHECK_THROWS_AS(level_traits(ModelChoice::automatic), std::logic_error);
}
