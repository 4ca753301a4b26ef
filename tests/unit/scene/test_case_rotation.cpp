// [rotation]: speeds, web speeds, excitation orders; each mistake refused
// with file:line:col, the key and what is expected.
#include "scene/case_file.hpp"
#include "scene/rotation_spec.hpp"
#include "effects/rotation.hpp"

#include "common/error.hpp"

#include "support/case_errors.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

namespace {

const std::string kCore =
    "[core]\n"
    "inner_diameter = \"76 mm\"\n"
    "outer_diameter = \"106 mm\"\n"
    "length = \"1.5 m\"\n";

RotatingCase read(const std::string& rotation) { return parse_rotating_case_text(kCore + rotation, "cases/x.toml"); }

}  // namespace

TEST_CASE("A scene spins only with [rotation]", "[rotation][scene]") {
    const RotatingCase still = read("");
    CHECK_FALSE(still.rotation);
    const std::vector<std::string> effects = still.scene.effects();
    CHECK(std::find(effects.begin(), effects.end(), "gyroscopic") == effects.end());
    const RotatingCase spinning = read("[rotation]\nspeed = \"1200 rpm\"\n");
    REQUIRE(spinning.rotation);
    CHECK(spinning.rotation->speeds_hz == std::vector<double>{20.0});
    CHECK_FALSE(spinning.rotation->sweep());
    CHECK(spinning.rotation->excitation_orders == std::vector<int>{1, 2});
    CHECK(spinning.rotation->centrifugal_stiffening);
    CHECK(rotating_effect_names(spinning.scene, *spinning.rotation).back() == "gyroscopic");
    CHECK(rotating_effect_names(spinning.scene, *spinning.rotation, true).back() == "centrifugal_stiffening");
}

TEST_CASE("[rotation] speeds: a range with points, or a list", "[rotation][scene]") {
    const RotatingCase range = read("[rotation]\nspeeds = [\"0 rpm\", \"4000 rpm\"]\npoints = 41\n");
    REQUIRE(range.rotation->speeds_hz.size() == 41);
    CHECK(range.rotation->speeds_hz.front() == 0.0);
    CHECK(range.rotation->speeds_hz[1] == Approx(100.0 / 60));
    CHECK(range.rotation->speeds_hz.back() == Approx(4000.0 / 60));
    const RotatingCase list = read("[rotation]\nspeeds = [\"0 Hz\", \"10 Hz\", \"25 Hz\"]\nexcitation_orders = [1, 2, 3]\n"
                            "centrifugal_stiffening = false\n");
    CHECK(list.rotation->speeds_hz == std::vector<double>{0, 10, 25});
    CHECK(list.rotation->excitation_orders == std::vector<int>{1, 2, 3});
    CHECK_FALSE(list.rotation->centrifugal_stiffening);
}

TEST_CASE("[rotation] web speeds turn into rotation frequencies at the roll's outer diameter", "[rotation][scene]") {
    // f_rot = v / (pi Dp): 15 m/s on a 106 mm core.
    const RotatingCase bare = read("[rotation]\nweb_speed = \"15 m/s\"\n");
    CHECK(bare.rotation->from_web_speed);
    CHECK(bare.rotation->speeds_hz.front() == Approx(15 / (M_PI * 0.106)).epsilon(1e-14));
    // With rest paper Dp is the paper's outer diameter.
    const RotatingCase paper = parse_rotating_case_text(kCore + "[rest_paper]\nouter_diameter = \"300 mm\"\n[rotation]\n"
                                                "web_speeds = [\"0 m/s\", \"30 m/s\"]\npoints = 3\n",
                                        "cases/x.toml");
    REQUIRE(paper.rotation->speeds_hz.size() == 3);
    CHECK(paper.rotation->speeds_hz[2] == Approx(30 / (M_PI * 0.3)).epsilon(1e-14));
}

TEST_CASE("[rotation] mistakes are refused with the key, the place and what is expected", "[rotation][scene]") {
    CHECK(error_of(kCore + "[rotation]\nexcitation_orders = [1]\n") ==
          "cases/x.toml:5:1: [rotation] gives no speed; expected exactly one of speed = \"1200 rpm\", speeds = [\"0 rpm\", "
          "\"4000 rpm\"] (with points = 41, or a list), web_speed = \"15 m/s\" or web_speeds = [...]");
    CHECK(error_of(kCore + "[rotation]\nspeed = \"10 Hz\"\nweb_speed = \"5 m/s\"\n").starts_with(
        "cases/x.toml:7:13: [rotation] web_speed = \"5 m/s\" and [rotation] speed = \"10 Hz\" are both given"));
    CHECK(error_of(kCore + "[rotation]\nspeed = \"10 m\"\n").starts_with("cases/x.toml:6:9: [rotation] speed = \"10 m\": "));
    CHECK(error_of(kCore + "[rotation]\nspeed = 4000\n") ==
          "cases/x.toml:6:9: [rotation] speed = 4000 Hz is too large: expected at most 1000 Hz; plain numbers are in Hz");
    CHECK(error_of(kCore + "[rotation]\nspeeds = [\"10 Hz\", \"5 Hz\"]\n") ==
          "cases/x.toml:6:20: [rotation] speeds = [\"10 Hz\", \"5 Hz\"]: the speeds must increase from one to the next");
    CHECK(error_of(kCore + "[rotation]\nspeeds = [\"1 Hz\", \"5 Hz\", \"9 Hz\"]\npoints = 5\n") ==
          "cases/x.toml:7:10: [rotation] points = 5 needs [rotation] speeds = [\"1 Hz\", \"5 Hz\", \"9 Hz\"] to be "
          "[first, last]; expected two speeds, or a list without points");
    CHECK(error_of(kCore + "[rotation]\nspeed = \"5 Hz\"\npoints = 5\n") ==
          "cases/x.toml:7:10: [rotation] points = 5 goes with speeds or web_speeds = [first, last]; expected no points "
          "with speed");
    CHECK(error_of(kCore + "[rotation]\nspeed = \"5 Hz\"\nexcitation_orders = [0.5]\n") ==
          "cases/x.toml:7:22: [rotation] excitation_orders = [0.5]: expected whole numbers from 1 to 20, e.g. [1, 2]");
    CHECK(error_of(kCore + "[rotation]\nspeed = \"5 Hz\"\nexcitation_orders = [1, 1]\n") ==
          "cases/x.toml:7:25: [rotation] excitation_orders = [1, 1]: order 1 is given twice");
    CHECK(error_of(kCore + "[rotation]\nsped = \"5 Hz\"\n") ==
          "cases/x.toml:6:1: unknown key 'sped' in [rotation]; did you mean 'speed'?");
}

// operating_speeds: two speeds in the sweep's units, the lower first, inside the sweep.
TEST_CASE("[rotation] operating_speeds: the range read, mistakes refused naming the key", "[rotation][scene]") {
    const std::string sweep = "[rotation]\nspeeds = [\"0 rpm\", \"4500 rpm\"]\npoints = 10\n";
    const RotatingCase good = read(sweep + "operating_speeds = [\"600 rpm\", \"4000 rpm\"]\n");
    REQUIRE(good.rotation->operating_hz);
    CHECK((*good.rotation->operating_hz)[0] == Approx(10.0));  // 600 rpm = 10 Hz
    CHECK((*good.rotation->operating_hz)[1] == Approx(4000.0 / 60));
    CHECK_FALSE(read(sweep).rotation->operating_hz);
    const std::string reversed = error_of(kCore + sweep + "operating_speeds = [\"4000 rpm\", \"600 rpm\"]\n");
    CHECK(reversed.starts_with("cases/x.toml:8:"));
    CHECK(reversed.find("[rotation] operating_speeds = ") != std::string::npos);
    CHECK(reversed.find("the lowest speed must come first and be below the highest") != std::string::npos);
    CHECK(error_of(kCore + sweep + "operating_speeds = [\"600 rpm\", \"600 rpm\"]\n").find("below the highest") !=
          std::string::npos);
    const std::string unit = error_of(kCore + sweep + "operating_speeds = [\"0 rpm\", \"15 m/s\"]\n");
    CHECK(unit.starts_with("cases/x.toml:8:"));
    CHECK(unit.find("[rotation] operating_speeds = ") != std::string::npos);
    CHECK(error_of(kCore + sweep + "operating_speeds = [\"0 rpm\", \"5000 rpm\"]\n").find("outside the sweep") !=
          std::string::npos);
    CHECK(error_of(kCore + "[rotation]\nspeed = \"10 Hz\"\noperating_speeds = [\"0 rpm\", \"600 rpm\"]\n")
              .find("goes with a sweep") != std::string::npos);
}
