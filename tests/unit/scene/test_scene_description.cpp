// The resolved scene as text (scene/scene_description): the key paths a file
// gives, and each value's origin.
#include "scene/scene_description.hpp"

#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;

namespace {

const std::string kChucks = R"(
[core]
inner_diameter = "76 mm"
outer_diameter = "106 mm"
length = "2 m"
material = { base = "paperboard_core", E_z = "7 GPa" }

[supports]
type = "chucks"

[supports.left]
inserted_length = "110 mm"
body_diameter = "75 mm"

[[supports.left.expanding]]
center = "70 mm"
width = "40 mm"

[[supports.left.expanding]]
center = "20 mm"
width = "20 mm"
)";

}  // namespace

TEST_CASE("key_sources gives the dotted path of every key, items of arrays of tables from 1", "[scene][description]") {
    const KeySources s = key_sources(kChucks);
    for (const char* path : {"core", "core.inner_diameter", "core.material", "core.material.E_z", "supports.type",
                             "supports.left.body_diameter", "supports.left.expanding", "supports.left.expanding.1",
                             "supports.left.expanding.2.width"})
        CHECK(s.in_file_has(path));
    CHECK_FALSE(s.in_file_has("core.material.E_r"));
    CHECK_FALSE(s.in_file_has("supports.right"));
    CHECK_FALSE(s.in_file_has("supports.left.expanding.3"));
    CHECK(key_sources("[core\nnot toml").in_file.empty());
}

TEST_CASE("describe_scene says where each value came from", "[scene][description]") {
    const Scene scene = parse_case_text(kChucks, "x.toml");
    const std::string text = describe_scene(scene, key_sources(kChucks));
    INFO(text);
    const auto line_of = [&](const std::string& start) {
        const std::size_t at = text.find("  " + start);
        return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
    };
    CHECK_THAT(line_of("[core] outer_diameter = 0.106 m"), Catch::EndsWith("   file"));
    CHECK_THAT(line_of("[core] material = \"paperboard_core (modified)\""), Catch::EndsWith("   file"));
    CHECK_THAT(line_of("[core.material] E_z = 7 GPa"), Catch::EndsWith("   file"));
    CHECK_THAT(line_of("[core.material] E_r = 33 MPa"), Catch::EndsWith("   library 'paperboard_core'"));
    CHECK_THAT(line_of("[supports.left] body_diameter = 0.075 m"), Catch::EndsWith("   file"));
    CHECK_THAT(line_of("[supports.left] shaft_diameter = 0.075 m"), Catch::EndsWith("default: the body diameter"));
    CHECK_THAT(line_of("[supports.left.expanding #2] width = 0.02 m"), Catch::EndsWith("   file"));
    CHECK_THAT(line_of("[supports.right.expanding #2] width = 0.02 m"), Catch::EndsWith("mirrors [supports.left]"));
    CHECK_THAT(line_of("[supports.left] interface = \"spring\""), Catch::EndsWith("   default"));
    CHECK_THAT(line_of("[supports.left] normal_stiffness"),
               Catch::EndsWith("from expansion_pressure = 600 kPa (default)"));
    CHECK_THAT(line_of("[analysis] modes = 20"), Catch::EndsWith("   default"));

    const std::string effects = describe_effects(scene);
    CHECK_THAT(effects, Catch::Contains("  elastic_chucks  "));
    CHECK_THAT(effects, Catch::Contains("  contact_compliance  "));
    CHECK_THAT(effects, !Catch::Contains("bearing_springs"));
}
