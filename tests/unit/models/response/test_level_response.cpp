// ModelLevel::response: the level object `coremodal response` drives
// (models/response/level_response.hpp).
#include "analyses/response/response.hpp"
#include "common/error.hpp"
#include "models/choose.hpp"
#include "models/response/level_response.hpp"
#include "scene/case_file.hpp"

#include "support/response_setup.hpp"
#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;

namespace {

Scene roll_at(const std::string& model) {
    std::string text = testing::kClampedRestRoll;
    text.replace(text.find("\"beam\""), 6, "\"" + model + "\"");
    return parse_case_text(text, "roll.toml");
}

ResponseSetup unbalanced(double kg_m) {
    ExcitationSpec x;
    x.unbalance_kg_m = kg_m;
    return testing::response_setup(0.01, x, 5, 40, 30, 2.0);
}

}  // namespace

TEST_CASE("A level without a forced response refuses it, saying why", "[response][models]") {
    const Scene scene = roll_at("coupled");
    // The level traits' reason (scene/level_traits.cpp), as require_response_level words it.
    CHECK_THROWS_AS(make_model_level(scene)->response(scene, {}), InputError);
    CHECK_THROWS_WITH(make_model_level(scene)->response(scene, {}),
                      Catch::Contains("roll.toml: [response] at the coupled level: the coupled harmonics have no "
                                      "spinning terms yet"));
}

TEST_CASE("A level's response to several setups is each setup's: linear in the unbalance", "[response][models]") {
    // The beam level answers a batch one setup after another (LevelResponse::respond_all's default).
    const Scene scene = roll_at("beam");
    const std::vector<ResponseResult> both = make_model_level(scene)->response(scene, {})->respond_all(
        {unbalanced(2e-3), unbalanced(6e-3)}, ResponseChecking::none, RestModes::lateral);
    REQUIRE(both.size() == 2);
    CHECK(both[0].level == ModelChoice::beam);
    REQUIRE(both[0].max_amplitude_m > 0);
    // No gravity, no bow: the orbit is linear in the unbalance (round-off only).
    CHECK(both[1].max_amplitude_m == Approx(3 * both[0].max_amplitude_m).epsilon(1e-9));
    CHECK(both[1].max_amplitude_web_speed_m_s == Approx(both[0].max_amplitude_web_speed_m_s).epsilon(1e-9));
}
