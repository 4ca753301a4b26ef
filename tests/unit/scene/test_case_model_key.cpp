// The top-level `model` key: which model level runs the scene.
#include "scene/case_file.hpp"

#include "common/error.hpp"

#include "support/case_errors.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

namespace {

const std::string kCore =
    "[core]\n"
    "inner_diameter = \"76 mm\"\n"
    "outer_diameter = \"106 mm\"\n"
    "length = \"1.5 m\"\n";

}  // namespace

TEST_CASE("The model level is solid unless the case file says another; each word reads back as itself",
          "[scene][case_file][model]") {
    CHECK(parse_case_text(kCore, "cases/x.toml").model == ModelChoice::solid);
    CHECK(parse_case_text("model = \"beam\"\n" + kCore, "cases/x.toml").model == ModelChoice::beam);
    CHECK(parse_case_text("model = \"auto\"\n" + kCore, "cases/x.toml").model == ModelChoice::automatic);
    // The words of docs/reference/case-files.md ("model"): case file -> enum -> the word summary.json and report.md write.
    for (const std::string word : {"solid", "harmonic", "coupled", "auto", "beam"})
        CHECK(to_string(parse_case_text("model = \"" + word + "\"\n" + kCore, "cases/x.toml").model) == word);
}

TEST_CASE("An unknown model level names file, line, key and the levels there are", "[scene][case_file][model]") {
    CHECK(error_of("model = \"beem\"\n" + kCore) ==
          "cases/x.toml:1:9: model = \"beem\": unknown value; did you mean \"beam\"?; expected one of solid, harmonic, coupled, auto, beam");
    CHECK(error_of("model = \"shell\"\n" + kCore) ==
          "cases/x.toml:1:9: model = \"shell\": unknown value; expected one of solid, harmonic, coupled, auto, beam");
    CHECK(error_of("model = 1\n" + kCore) == "cases/x.toml:1:9: model = 1: expected a string in quotes");
    CHECK(error_of("modle = \"beam\"\n" + kCore) ==
          "cases/x.toml:1:1: unknown key 'modle' at the top level; did you mean 'model'?");
}
