// Reading a winder case file: defaults, units, and errors that name the file,
// line, column and key, say what is wrong and what is expected.
#include "winder/winder_scene.hpp"

#include "common/error.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace coremodal;

namespace {

// The message of the InputError that reading `text` throws ("" if none).
std::string error_of(const std::string& text) {
    try {
        read_winder_text(text, "w.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("A bare [winder] table gives the paper's example winder", "[winder][scene]") {
    const WinderScene s = read_winder_text("[winder]\n", "cases/w.toml");
    CHECK(s.name == "w");
    CHECK(s.drums.outer_diameter == 0.85);
    CHECK(s.drums.wall == 0.05);
    CHECK(s.drums.length == 10.0);
    CHECK(s.rolls.count == 5);
    CHECK(s.rolls.width == 1.68);
    CHECK(s.rolls.radial_modulus == 9.8e6);
    CHECK(s.rolls.poisson == 0.3);
    CHECK(s.rider.length == 9.1);
    CHECK(s.rolls.model == RollModel::rigid);
    CHECK(!s.drums.line_load);
    CHECK(s.drums.bearing_stiffness_horizontal == s.drums.bearing_stiffness_vertical);
    // Every physical default in use is listed with where it comes from.
    const auto listed = [&](const std::string& line) {
        return std::find(s.defaults.begin(), s.defaults.end(), line) != s.defaults.end();
    };
    CHECK(listed("[winder.drums] outer_diameter = 0.85 m (paper)"));
    CHECK(listed("[winder.drums] gap = 0.1 m (assumed)"));
    CHECK(listed("[winder.rolls] radial_modulus = 9.8 MPa (paper)"));
    CHECK(listed("[winder.rider] material = \"steel\" (assumed)"));
    CHECK(!listed("[winder.sweep] points = 57"));  // a setting, not physics
}

TEST_CASE("Winder values take units and land in SI", "[winder][scene]") {
    const WinderScene s = read_winder_text(R"(
name = "mill 3"
[winder]
web_speed = "2400 m/min"
[winder.drums]
outer_diameter = "1000 mm"
bearing_stiffness = "500 MN/m"
bearing_stiffness_horizontal = "2 kN/mm"
line_load = "8 kN/m"
[winder.rolls]
model = "beam"
paper_density = "0.9 g/cm^3"
radial_modulus = "12 MPa"
diameter_end = "1500 mm"
[winder.sweep]
points = 11
max_frequency = "3000 rpm"
response_drum = "rear"
response_direction = "horizontal"
)",
                                           "w.toml");
    CHECK(s.name == "mill 3");
    CHECK(std::none_of(s.defaults.begin(), s.defaults.end(),
                       [](const std::string& d) { return d.find("radial_modulus") != std::string::npos; }));
    CHECK(s.web_speed == Approx(40.0));
    CHECK(s.drums.outer_diameter == Approx(1.0));
    CHECK(s.drums.bearing_stiffness_vertical == Approx(5e8));
    CHECK(s.drums.bearing_stiffness_horizontal == Approx(2e6));
    CHECK(*s.drums.line_load == Approx(8000));
    CHECK(s.rolls.model == RollModel::beam);
    CHECK(s.rolls.paper_density == Approx(900));
    CHECK(s.rolls.radial_modulus == Approx(12e6));
    CHECK(s.rolls.diameter_end == Approx(1.5));
    CHECK(s.sweep.points == 11);
    CHECK(s.sweep.max_frequency == Approx(50.0));
    CHECK(s.sweep.response_drum == DrumSide::rear);
    CHECK(s.sweep.response_direction == ResponseDirection::horizontal);
}

TEST_CASE("A misspelt winder key names its place and the nearest key", "[winder][scene]") {
    const std::string e = error_of("[winder]\n[winder.drums]\nwal = \"40 mm\"\n");
    CHECK(e.find("w.toml:3:1:") == 0);
    CHECK(e.find("unknown key 'wal' in [winder.drums]") != std::string::npos);
    CHECK(e.find("did you mean 'wall'?") != std::string::npos);
}

TEST_CASE("Bad winder values are refused with what was expected", "[winder][scene]") {
    SECTION("a negative length") {
        const std::string e = error_of("[winder.drums]\nwall = \"-5 mm\"\n");
        CHECK(e.find("w.toml:2:8: [winder.drums] wall = \"-5 mm\": out of range; expected a value > 0 m") == 0);
    }
    SECTION("a unit of the wrong kind") {
        const std::string e = error_of("[winder.rolls]\nwidth = \"1.68 MPa\"\n");
        CHECK(e.find("w.toml:2:9: [winder.rolls] width") == 0);
        CHECK(e.find("expected a length") != std::string::npos);
    }
    SECTION("a line load named as one") {
        const std::string e = error_of("[winder.rider]\nline_load = true\n");
        CHECK(e.find("expected a line load") != std::string::npos);
    }
    SECTION("a whole number with a decimal point") {
        CHECK(error_of("[winder.rolls]\ncount = 5.0\n").find("expected a whole number") != std::string::npos);
    }
    SECTION("an unknown roll model") {
        const std::string e = error_of("[winder.rolls]\nmodel = \"elastic\"\n");
        CHECK(e.find("w.toml:2:9: [winder.rolls] model = \"elastic\": expected one of rigid, beam") == 0);
    }
    SECTION("an unknown material") {
        CHECK(error_of("[winder.drums]\nmaterial = \"unobtainium\"\n").find("no such library material") !=
              std::string::npos);
    }
    SECTION("a wall thicker than the drum's radius") {
        CHECK(error_of("[winder.drums]\nwall = \"500 mm\"\n").find("must be less than half the outer diameter") !=
              std::string::npos);
    }
    SECTION("no [winder] table") {
        CHECK(error_of("name = \"x\"\n").find("no [winder] table") != std::string::npos);
    }
    SECTION("a TOML syntax error") {
        CHECK(error_of("[winder\n").find("w.toml:1:") == 0);
    }
}

TEST_CASE("Winder geometry that cannot be is refused", "[winder][scene]") {
    SECTION("rolls longer than the drums") {
        const std::string e = error_of("[winder.rolls]\ncount = 7\n");  // 7 x 1.68 = 11.76 m > 10 m
        CHECK(e.find("w.toml:1:1: the row of rolls (7 x 1.68 m") == 0);
        CHECK(e.find("is longer than [winder.drums] length = 10 m") != std::string::npos);
    }
    SECTION("rolls longer than the rider") {
        CHECK(error_of("[winder.rider]\nlength = \"8 m\"\n").find("expected the rider to cover every roll") !=
              std::string::npos);
    }
    SECTION("a first roll that falls between the drums") {
        const std::string e = error_of("[winder.drums]\ngap = \"450 mm\"\n");
        CHECK(e.find("the roll would fall between them") != std::string::npos);
    }
    SECTION("a roll smaller than its core") {
        CHECK(error_of("[winder.rolls]\ndiameter_start = \"150 mm\"\n").find("is smaller than the core") !=
              std::string::npos);
    }
    SECTION("an end diameter below the start") {
        CHECK(error_of("[winder.rolls]\ndiameter_end = \"300 mm\"\n").find("must be larger than diameter_start") !=
              std::string::npos);
    }
}
