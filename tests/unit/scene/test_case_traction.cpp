// [traction] through the case reader (scene/traction_case.hpp): a file for
// `coremodal traction` alone and a stand scene with [traction] beside [web];
// every mistake refused with the place, the key and what is expected.
#include "scene/case_file.hpp"
#include "scene/traction_case.hpp"
#include "support/case_errors.hpp"

#include "common/error.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

namespace {

// Roller 4 of Rice & Gans under web 8 (Tables 1-3), 0-20 m/s.
const std::string kGrooved = R"(name = "roller-4"
[traction]
roller_radius = "50.8 mm"
wrap = "88 deg"
tension = "350 N/m"
friction = 0.16
roller_roughness = "0.38 um"
web_roughness = "1.11 um"
grooves = "circular"
groove_depth = "36 um"
groove_width = "175.3 um"
groove_pitch = "254 um"
tool_radius = "127 um"
web_thickness = "125 um"
web_density = "1358 kg/m^3"
web_modulus = "4.83 GPa"
web_poisson = 0.3
web_speeds = ["0 m/s", "20 m/s"]
points = 5
)";

// Roller 2 (plain) under web 5 at 44 N/m; no speeds: the default range.
const std::string kPlain = R"([traction]
roller_radius = 0.05
wrap = "90 deg"
tension = 44
friction = 0.55
roller_roughness = "25.9 um"
web_roughness = "1.54 um"
web_thickness = "180 um"
web_density = 1358
)";

TractionCase read(const std::string& text) {
    const std::optional<TractionCase> tc = read_traction_case_text(text, "cases/t.toml");
    REQUIRE(tc);
    return *tc;
}

std::string error_in(const std::string& text) {
    try {
        read_traction_case_text(text, "cases/t.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// kGrooved with one line replaced (or removed, with an empty `to`).
std::string changed(const std::string& from, const std::string& to, const std::string& text = kGrooved) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    std::string out = text;
    out.replace(at, from.size(), to);
    return out;
}

}  // namespace

TEST_CASE("[traction] is read in SI units with its speeds", "[traction][scene]") {
    const TractionCase tc = read(kGrooved);
    const TractionSpec& s = tc.spec;
    CHECK(tc.name == "roller-4");
    CHECK_FALSE(tc.has_roll);
    CHECK(s.roller_radius == Approx(0.0508).epsilon(1e-15));
    CHECK(s.wrap == Approx(88 * std::numbers::pi / 180).epsilon(1e-15));
    CHECK(s.grooves.shape == GrooveShape::circular);
    CHECK(s.grooves.land_width() == Approx(78.7e-6).epsilon(1e-12));
    CHECK(s.web_modulus == 4.83e9);
    CHECK(s.web_speeds == std::vector<double>{0, 5, 10, 15, 20});
    CHECK(tc.speeds_given);
    // The one default: the air's viscosity, echoed with its source.
    REQUIRE(tc.assumptions.size() == 1);
    CHECK(tc.assumptions[0].starts_with("[traction] air_viscosity = 1.81e-5 Pa*s: air at room temperature"));
    CHECK(s.air_viscosity == kAirViscosity);
    CHECK(tc.warnings.empty());
}

TEST_CASE("Without speeds a [traction] runs from 0 to 1.25 x its zero-traction speed", "[traction][scene]") {
    const TractionCase tc = read(kPlain);
    CHECK_FALSE(tc.speeds_given);
    REQUIRE(tc.spec.web_speeds.size() == kDefaultSpeedPoints);
    CHECK(tc.spec.web_speeds.front() == 0.0);
    CHECK(tc.spec.web_speeds.back() == Approx(1.25 * zero_traction_speed(tc.spec)).epsilon(1e-12));
    CHECK(tc.spec.grooves.shape == GrooveShape::none);
    CHECK(read(changed("tension = 44", "tension = 44\nair_viscosity = \"0.0181 mPa*s\"", kPlain)).spec.air_viscosity ==
          Approx(1.81e-5).epsilon(1e-12));
}

TEST_CASE("[traction] mistakes are refused with the place, the key and what is expected", "[traction][scene]") {
    CHECK(error_in(changed("wrap = \"88 deg\"", "wrap = \"0 deg\"")) ==
          "cases/t.toml:4:8: [traction] wrap = 0 rad must be positive");
    CHECK(error_in(changed("wrap = \"88 deg\"", "wrap = \"-10 deg\"")).starts_with("cases/t.toml:4:8: [traction] wrap"));
    CHECK(error_in(changed("web_roughness = \"1.11 um\"", "web_roughness = \"-1 um\"")) ==
          "cases/t.toml:8:17: [traction] web_roughness = -1e-06 m must be zero or positive");
    CHECK(error_in(changed("groove_depth = \"36 um\"", "groove_depth = \"-36 um\"")) ==
          "cases/t.toml:10:16: [traction] groove_depth = -3.6e-05 m must be positive");
    CHECK(error_in(changed("wrap = \"88 deg\"", "wrap = \"88 mm\"")).starts_with(
        "cases/t.toml:4:8: [traction] wrap = \"88 mm\": unit 'mm' is a length, expected an angle"));
    CHECK(error_in(changed("friction = 0.16", "fricton = 0.16")).starts_with(
        "cases/t.toml:6:1: unknown key 'fricton' in [traction]; did you mean 'friction'?"));
    CHECK(error_in(changed("friction = 0.16\n", "")) ==
          "cases/t.toml:2:1: [traction] friction is missing; expected the static coefficient of friction of web on "
          "roller, e.g. friction = 0.3");
    CHECK(error_in(changed("grooves = \"circular\"", "grooves = \"circlar\"")).starts_with(
        "cases/t.toml:9:11: [traction] grooves = \"circlar\": unknown value; did you mean \"circular\"?"));
    CHECK(error_in(changed("grooves = \"circular\"", "grooves = \"knurled\"")) ==
          "cases/t.toml:9:11: [traction] grooves = \"knurled\": unknown value; expected one of none, sine, circular, "
          "rectangular");
    SECTION("A plain roller with perfectly smooth surfaces has no clearance for the air") {
        CHECK(error_in(changed("roller_roughness = \"25.9 um\"\nweb_roughness = \"1.54 um\"",
                               "roller_roughness = 0\nweb_roughness = 0", kPlain))
                  .starts_with("cases/t.toml:1:1: [traction] roller_roughness = 0 and web_roughness = 0 on a plain "
                               "roller: the effective clearance h_eff is zero"));
    }
    SECTION("Grooves that do not fit: wider than the pitch, than the tool cuts, deeper than the tool") {
        CHECK(error_in(changed("groove_width = \"175.3 um\"", "groove_width = \"300 um\"")).starts_with(
            "cases/t.toml:11:16: [traction] groove_width = 300 um is wider than [traction] groove_pitch = 254 um"));
        CHECK(error_in(changed("groove_width = \"175.3 um\"", "groove_width = \"200 um\"")).starts_with(
            "cases/t.toml:11:16: [traction] groove_width = 200 um is wider than the 177.2 um a tool of radius 127 um "
            "cuts 36 um deep"));
        CHECK(error_in(changed("tool_radius = \"127 um\"", "tool_radius = \"30 um\"")).starts_with(
            "cases/t.toml:10:16: [traction] groove_depth = 36 um is deeper than [traction] tool_radius = 30 um"));
        CHECK(error_in(changed("tool_radius = \"127 um\"\n", "")).starts_with(
            "cases/t.toml:2:1: [traction] tool_radius is missing"));
        CHECK(error_in(changed("grooves = \"circular\"", "grooves = \"none\"")).starts_with(
            "cases/t.toml:10:16: [traction] groove_depth = \"36 um\" describes grooves, but the roller has none"));
        CHECK(error_in(changed("web_modulus = \"4.83 GPa\"\n", "")).starts_with(
            "cases/t.toml:2:1: [traction] web_modulus is missing; expected the web's Young's modulus with grooves"));
    }
    SECTION("Speeds at which the web's inertia takes its whole tension") {
        // sqrt(350 / (125e-6 x 1358)) = 45.4 m/s
        CHECK(error_in(changed("web_speeds = [\"0 m/s\", \"20 m/s\"]", "web_speeds = [\"0 m/s\", \"50 m/s\"]"))
                  .starts_with("cases/t.toml:18:14: [traction] web_speeds: 50 m/s is at or above 45.4 m/s, where the "
                               "web's centripetal term"));
        CHECK(error_in(changed("points = 5", "web_speed = \"3 m/s\""))
                  .starts_with("cases/t.toml:18:14: [traction] web_speeds = [\"0 m/s\", \"20 m/s\"] and [traction] "
                               "web_speed = \"3 m/s\" are both given"));
    }
}

TEST_CASE("A [traction] file given to run is pointed to coremodal traction", "[traction][scene]") {
    CHECK(error_of(kGrooved) == "cases/x.toml:2: [traction] without [core] is a roller's traction file, not a roll's "
                                "case file; run it with `coremodal traction cases/x.toml` (docs/how-to/traction.md)");
}

TEST_CASE("[traction] beside [web] in a stand scene: checked, and the scene is the same without it",
          "[traction][scene]") {
    const std::string roll = R"(name = "stand"
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2.2 m"
[supports]
type = "clamped"
[supports.left]
length = "70 mm"
[web]
tension = "300 N/m"
span = "1 m"
angle = "30 deg"
thickness = "80 um"
modulus = "5 GPa"
)";
    const std::string traction = changed("name = \"roller-4\"\n", "");
    const Scene without = parse_case_text(roll, "cases/x.toml");
    const Scene with = parse_case_text(roll + traction, "cases/x.toml");
    CHECK(with.assumptions == without.assumptions);
    CHECK(with.warnings == without.warnings);
    CHECK(with.web->tension == without.web->tension);
    const TractionCase tc = read(roll + traction);
    CHECK(tc.has_roll);
    CHECK(tc.name == "stand");
    CHECK(tc.spec.tension == 350);
    CHECK(zero_traction_speed(tc.spec) > 20);
    // A mistake in [traction] is a mistake of the scene, for every command.
    CHECK(error_of(roll + changed("wrap = \"88 deg\"", "wrap = 0", traction)) ==
          "cases/x.toml:18:8: [traction] wrap = 0 rad must be positive");
    // ... and a mistake in the scene stops `coremodal traction` too.
    CHECK(error_in(changed("wall = \"15 mm\"", "wall = \"-15 mm\"", roll) + traction)
              .starts_with("cases/t.toml:4:8: [core] wall"));
    CHECK_FALSE(read_traction_case_text(roll, "cases/x.toml"));
}
