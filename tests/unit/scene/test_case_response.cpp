// [damping], [excitation], [response]: values, defaults, web speeds at Dp,
// and each mistake refused with file:line:col, the key and what is expected.
#include "effects/damping.hpp"
#include "effects/excitation.hpp"
#include "scene/case_file.hpp"
#include "scene/response_spec.hpp"

#include "common/error.hpp"

#include "support/case_errors.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

namespace {

// 11 lines: the tables under test start on line 12.
const std::string kRoll =
    "[core]\n"
    "inner_diameter = \"150 mm\"\n"
    "outer_diameter = \"176 mm\"\n"
    "length = \"2 m\"\n"
    "[supports]\n"
    "type = \"clamped\"\n"
    "[supports.left]\n"
    "length = \"100 mm\"\n"
    "start = \"0 mm\"\n"
    "[rest_paper]\n"
    "thickness = \"10 mm\"\n";
const std::string kDamping = "[damping]\nratio = 0.01\n";
const std::string kExcitation = "[excitation]\nbow = \"0.5 mm\"\n";
const std::string kResponse = "[response]\nweb_speeds = [\"5 m/s\", \"20 m/s\"]\npoints = 4\n";

ResponseCase read(const std::string& tables) { return parse_response_case_text(kRoll + tables, "cases/x.toml"); }

}  // namespace

TEST_CASE("Only a scene with [response] simulates damping and excitation", "[response][scene]") {
    CHECK_FALSE(read("").response);
    const ResponseCase c = read(kDamping + kExcitation + kResponse);
    REQUIRE(c.response);
    CHECK(c.response->damping.ratio == 0.01);
    CHECK(c.response->excitation.bow_m == Approx(0.5e-3).epsilon(1e-14));
    CHECK(c.response->excitation.bow_shape == BowShape::half_sine);
    CHECK(c.response->excitation.gravity);
    CHECK(excitation_effect_names(c.response->excitation) == std::vector<std::string>{"bow", "gravity"});
    // Defaults: the +-5 mm limit at mid-span (Ilomäki).
    CHECK(c.response->response.limit_m == kDefaultAmplitudeLimit);
    REQUIRE(c.response->response.probes.size() == 1);
    CHECK(c.response->response.probes[0].name == "mid-span");
    CHECK(c.response->response.probes[0].z_m == 1.0);
    // Web speeds at Dp = 176 + 2 x 10 mm: f_rot = v / (pi Dp).
    REQUIRE(c.response->response.speeds_hz.size() == 4);
    CHECK(c.response->response.from_web_speed);
    CHECK(c.response->response.speeds_hz.front() == Approx(5 / (M_PI * 0.196)).epsilon(1e-14));
    CHECK(c.response->response.speeds_hz.back() == Approx(20 / (M_PI * 0.196)).epsilon(1e-14));
}

TEST_CASE("[damping] from a ratio, a logarithmic decrement or a measured decay (I-1)", "[response][scene]") {
    const auto zeta = [](const std::string& damping) {
        return read("[damping]\n" + damping + kExcitation + kResponse).response->damping.ratio;
    };
    CHECK(zeta("log_decrement = 0.0628\n") == Approx(0.0628 / (2 * M_PI)).epsilon(1e-14));
    // A decay from 3.2 to 1 over 10 cycles: ln 3.2 / (20 pi) = 0.009257.
    CHECK(zeta("decay = { amplitude_ratio = 3.2, cycles = 10 }\n") == Approx(std::log(3.2) / (20 * M_PI)).epsilon(1e-14));
    CHECK(zeta_from_decay(std::exp(2 * M_PI * 0.01 * 7), 7) == Approx(0.01).epsilon(1e-14));
}

TEST_CASE("[excitation] and [response] keys: unbalance units, shapes, gravity, probes, speeds", "[response][scene]") {
    const ResponseCase c = read(kDamping +
                                "[excitation]\nunbalance = \"2 kg*mm\"\neccentricity = \"0.2 mm\"\novality = \"0.3 mm\"\n"
                                "bow = \"1 mm\"\nbow_shape = \"first_mode\"\ngravity = false\n"
                                "[response]\nspeeds = [\"100 rpm\", \"200 rpm\", \"600 rpm\"]\nlimit = \"3 mm\"\n"
                                "probes = [\"mid-span\", \"0.5 m\"]\n");
    const ExcitationSpec& x = c.response->excitation;
    CHECK(x.unbalance_kg_m == Approx(2e-3).epsilon(1e-14));
    CHECK(x.eccentricity_m == Approx(0.2e-3).epsilon(1e-14));
    CHECK(x.bow_shape == BowShape::first_mode);
    CHECK_FALSE(x.gravity);
    // An ovality without gravity excites nothing: not an effect of the run.
    CHECK(excitation_effect_names(x) == std::vector<std::string>{"unbalance", "eccentricity", "bow"});
    CHECK(c.response->response.speeds_hz == std::vector<double>{100.0 / 60, 200.0 / 60, 10.0});
    CHECK_FALSE(c.response->response.from_web_speed);
    CHECK(c.response->response.limit_m == Approx(3e-3).epsilon(1e-14));
    REQUIRE(c.response->response.probes.size() == 2);
    CHECK(c.response->response.probes[1].name == "z = 0.5 m");
    CHECK(c.response->response.probes[1].z_m == 0.5);
    CHECK(read(kDamping + "[excitation]\nunbalance = \"300 g*mm\"\n" + kResponse).response->excitation.unbalance_kg_m ==
          Approx(3e-4).epsilon(1e-14));
}

TEST_CASE("The ovality's stiffness split: thin-wall limit 3 delta / (2 R)", "[response][scene]") {
    // R = 0.1 m, wall 1 mm, ovality 0.4 mm: delta = 0.1 mm, eps -> 1.5e-3 (to O(t/R)).
    CHECK(ovality_stiffness_split(0.4e-3, 0.201, 0.199) == Approx(1.5e-3).epsilon(1e-4));
    // Thick: 2 delta (Ro^3 - Ri^3) / (Ro^4 - Ri^4) for the 150 x 13 core.
    const double ro = 0.088, ri = 0.075, delta = 0.3e-3 / 4;
    CHECK(ovality_stiffness_split(0.3e-3, 0.176, 0.150) ==
          Approx(2 * delta * (std::pow(ro, 3) - std::pow(ri, 3)) / (std::pow(ro, 4) - std::pow(ri, 4))).epsilon(1e-14));
}

TEST_CASE("[damping], [excitation], [response] mistakes are refused with the key, the place and what is expected",
          "[response][scene]") {
    CHECK(error_of(kRoll + kDamping) ==
          "cases/x.toml:12:1: [damping] is used only by the forced response and the Campbell diagram; expected a "
          "[response] table (web_speeds = [\"5 m/s\", \"20 m/s\"], points = 400) or a [rotation] table too, or no "
          "[damping] (docs/how-to/response.md)");
    CHECK(error_of(kRoll + kExcitation + kResponse).starts_with("cases/x.toml:14:1: [response] needs [damping]; "));
    CHECK(error_of(kRoll + kDamping + kResponse).starts_with("cases/x.toml:14:1: [response] needs [excitation]; "));
    CHECK(error_of(kRoll + "[damping]\n" + kExcitation + kResponse) ==
          "cases/x.toml:12:1: [damping] gives no damping for the modes it does not name; expected exactly one of "
          "ratio = 0.01, log_decrement = 0.06, decay = { amplitude_ratio = 3.2, cycles = 10 } or rayleigh = { zeta = "
          "0.01, frequencies = [\"20 Hz\", \"200 Hz\"] }, and/or a loss factor: loss_factor = 0.03 or "
          "[damping.loss_factors] core = 0.03");
    CHECK(error_of(kRoll + "[damping]\nratio = 0.01\nlog_decrement = 0.06\n" + kExcitation + kResponse)
              .starts_with("cases/x.toml:14:17: [damping] log_decrement = 0.06 and [damping] ratio = 0.01 are both given"));
    CHECK(error_of(kRoll + "[damping]\nratio = 1.5\n" + kExcitation + kResponse) ==
          "cases/x.toml:13:9: [damping] ratio = 1.5 is too large: expected at most 1");
    CHECK(error_of(kRoll + "[damping]\nratio = 0\n" + kExcitation + kResponse) ==
          "cases/x.toml:13:9: [damping] ratio = 0 must be positive");
    CHECK(error_of(kRoll + "[damping]\ndecay = { amplitude_ratio = 0.5, cycles = 3 }\n" + kExcitation + kResponse) ==
          "cases/x.toml:13:29: [damping.decay] amplitude_ratio = 0.5 must be larger than 1");
    CHECK(error_of(kRoll + "[damping]\ndecay = { amplitude_ratio = 3 }\n" + kExcitation + kResponse)
              .starts_with("cases/x.toml:13:9: [damping.decay] cycles is missing; expected N"));
    CHECK(error_of(kRoll + kDamping + "[excitation]\ngravity = true\n" + kResponse)
              .starts_with("cases/x.toml:14:1: [excitation] gives nothing that excites the roll; "));
    CHECK(error_of(kRoll + kDamping + "[excitation]\nunbalance = \"2 kg\"\n" + kResponse) ==
          "cases/x.toml:15:13: [excitation] unbalance = \"2 kg\": unit 'kg' is a mass, expected an unbalance (mass "
          "times eccentricity) (kg*m, kg*mm, g*mm)");
    CHECK(error_of(kRoll + kDamping + "[excitation]\nbow = \"0.5 mm\"\nbow_shape = \"sine\"\n" + kResponse)
              .starts_with("cases/x.toml:16:13: [excitation] bow_shape = \"sine\": unknown value"));
    CHECK(error_of(kRoll + kDamping + "[excitation]\novality = \"30 mm\"\n" + kResponse)
              .starts_with("cases/x.toml:15:11: [excitation] ovality = \"30 mm\" is more than a tenth of the core's outer "
                           "diameter 0.176 m"));
    CHECK(error_of(kRoll + kDamping + kExcitation + "[response]\npoints = 4\n")
              .starts_with("cases/x.toml:16:1: [response] gives no speeds; expected exactly one of web_speeds"));
    CHECK(error_of(kRoll + kDamping + kExcitation + "[response]\nweb_speeds = [\"0 m/s\", \"20 m/s\"]\npoints = 4\n")
              .starts_with("cases/x.toml:17:14: [response] web_speeds = [\"0 m/s\", \"20 m/s\"]: the roll must turn"));
    CHECK(error_of(kRoll + kDamping + kExcitation + kResponse + "probes = [\"3 m\"]\n") ==
          "cases/x.toml:19:11: [response] probes = [\"3 m\"]: 3 m is off the core; expected \"mid-span\" or a position "
          "from 0 to the core length 2 m");
    CHECK(error_of(kRoll + kDamping + kExcitation + kResponse + "probes = [\"mid-span\", \"1 m\"]\n") ==
          "cases/x.toml:19:23: [response] probes = [\"mid-span\", \"1 m\"]: z = 1 m is given twice");
    CHECK(error_of(kRoll + kDamping + kExcitation + kResponse + "limt = \"5 mm\"\n") ==
          "cases/x.toml:19:1: unknown key 'limt' in [response]; did you mean 'limit'?");
    // A free roll has no stand: refused.
    CHECK(error_of("[core]\ninner_diameter = \"76 mm\"\nouter_diameter = \"106 mm\"\nlength = \"1.5 m\"\n" + kDamping +
                   kExcitation + kResponse)
              .starts_with("cases/x.toml:9:1: [response] needs a roll held in its stand"));
}
