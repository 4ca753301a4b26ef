// Plausible ranges (scene/case_key_ranges.hpp, PlausibleRange): a value that
// parses but lies far outside what any roll has is most likely a unit slip
// (E = 6.5 is 6.5 Pa). The reader warns, naming the key and its place, and
// suggests the unit a plain number was probably meant in; the scene is still
// read with the value as written.
#include "scene/case_file.hpp"

#include "common/error.hpp"
#include "scene/case_schema.hpp"

#include <catch2/catch.hpp>

#include <string>

#ifndef COREMODAL_SOURCE_DIR
#define COREMODAL_SOURCE_DIR "."
#endif

using namespace coremodal;

namespace {

Scene read(const std::string& material, const std::string& length = "\"1.5 m\"") {
    return parse_case_text("[core]\n"
                           "inner_diameter = \"76 mm\"\n"
                           "wall = \"15 mm\"\n"
                           "length = " + length + "\n"
                           "material = " + material + "\n",
                           "cases/x.toml");
}

}  // namespace

TEST_CASE("A modulus given as a bare 6.5 is warned about, with its place, the range and the likely unit",
          "[scene][plausible]") {
    const Scene s = read("{ E = 6.5, nu = 0.3, density = 920 }");
    REQUIRE(s.warnings.size() == 1);
    const std::string& w = s.warnings[0];
    CHECK_THAT(w, Catch::StartsWith("cases/x.toml:5:"));
    CHECK_THAT(w, Catch::Contains("[core.material] E = 6.5 Pa is outside the plausible range 100 kPa to 1200 GPa"));
    CHECK_THAT(w, Catch::Contains("plain numbers are in Pa: did you mean \"6.5 GPa\"?"));
    CHECK_THAT(w, Catch::Contains("the run goes on"));
    // The value is read as written: a warning does not change the scene.
    CHECK(s.core.material.E_z == 6.5);
}

TEST_CASE("The suggested unit is the one nearest the key's typical value", "[scene][plausible]") {
    // Across the layers a paperboard shear modulus is tens of MPa: a bare 50 meant MPa.
    const Scene shear = read("{ base = \"paperboard_core\", G_rz = 50 }");
    REQUIRE(shear.warnings.size() == 1);
    CHECK_THAT(shear.warnings[0], Catch::Contains("did you mean \"50 MPa\"?"));
    // Density in g/cm^3 written bare.
    const Scene light = read("{ E = \"6.5 GPa\", nu = 0.3, density = 0.92 }");
    REQUIRE(light.warnings.size() == 1);
    CHECK_THAT(light.warnings[0], Catch::Contains("density = 0.92 kg/m^3") &&
                                      Catch::Contains("did you mean \"0.92 g/cm^3\"?"));
}

TEST_CASE("A slip that makes the material inadmissible is named in the error", "[scene][plausible]") {
    // E_r = 33 Pa against E_theta = 4 GPa: the compliance matrix is not
    // positive definite, an error; the likely cause is the missing unit.
    try {
        read("{ base = \"paperboard_core\", E_r = 33 }");
        FAIL("an inadmissible material was accepted");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("is not admissible") &&
                                 Catch::Contains("likely cause: cases/x.toml:5:") &&
                                 Catch::Contains("E_r = 33 Pa is outside the plausible range") &&
                                 Catch::Contains("did you mean \"33 MPa\"?"));
    }
}

TEST_CASE("A value with its unit is warned about without a suggestion; plausible values are not", "[scene][plausible]") {
    const Scene tiny = read("\"paperboard_core\"", "\"10 um\"");
    REQUIRE(tiny.warnings.size() == 1);
    CHECK_THAT(tiny.warnings[0], Catch::StartsWith("cases/x.toml:4:10: [core] length = 1e-05 m is outside the plausible range"));
    CHECK_THAT(tiny.warnings[0], !Catch::Contains("did you mean"));
    CHECK(read("{ E = \"6.5 GPa\", nu = 0.3, density = 920 }").warnings.empty());
    CHECK(read("\"paperboard_core\"", "\"5 mm\"").warnings.empty());  // a test ring cut from a core
}

TEST_CASE("Every example case reads without a plausibility warning", "[scene][plausible]") {
    for (const char* name : {"01-iso-free-free-76x15.toml", "03-rest-roll-150x15.8-4320.toml",
                             "07-rotogravure-chucks-150x15.8-4320.toml", "08-news-chucks-76x15-2200.toml"}) {
        INFO(name);
        CHECK(parse_case_file(std::string(COREMODAL_SOURCE_DIR) + "/cases/" + name).warnings.empty());
    }
}

TEST_CASE("Plausible ranges lie inside the hard limits of their keys", "[scene][plausible]") {
    for (const KeySpec& k : case_schema()) {
        if (k.plausible.empty()) continue;
        INFO("[" << k.table << "] " << k.key);
        CHECK(k.plausible.low >= k.min);
        CHECK(k.plausible.high <= k.max);
        CHECK(k.plausible.typical > k.plausible.low);
        CHECK(k.plausible.typical < k.plausible.high);
        CHECK_FALSE(k.plausible.why.empty());
    }
}
