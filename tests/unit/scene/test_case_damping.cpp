// [damping] beyond one ratio: Rayleigh (alpha and beta, or zeta at two
// frequencies), ratios per mode family and per mode; each mistake refused
// with file:line:col, the key and what is expected; `check`'s description.
#include "effects/damping.hpp"
#include "scene/case_file.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene_description.hpp"

#include "support/case_errors.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

namespace {

// 11 lines: [damping] starts on line 12, its first key on line 13.
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
const std::string kRest = "[excitation]\nbow = \"0.5 mm\"\n[response]\nweb_speeds = [\"5 m/s\", \"20 m/s\"]\npoints = 4\n";

DampingSpec damping_of(const std::string& keys) {
    return parse_response_case_text(kRoll + "[damping]\n" + keys + kRest, "cases/x.toml").response->damping;
}
std::string error_with(const std::string& keys) { return error_of(kRoll + "[damping]\n" + keys + kRest); }

}  // namespace

TEST_CASE("Rayleigh damping from zeta at two frequencies gives that zeta at both (closed form)", "[response][scene]") {
    const DampingSpec d = damping_of("rayleigh = { zeta = 0.01, frequencies = [\"20 Hz\", \"200 Hz\"] }\n");
    REQUIRE(d.rayleigh);
    const RayleighDamping r{d.rayleigh->alpha, d.rayleigh->beta};
    const double w1 = 2 * M_PI * 20, w2 = 2 * M_PI * 200;
    // alpha = 2 zeta w1 w2 / (w1 + w2), beta = 2 zeta / (w1 + w2) (Chopra, Dynamics of Structures, ch. 11),
    // computed here independently; 1e-14: a few operations' round-off.
    CHECK(r.alpha == Approx(2 * 0.01 * w1 * w2 / (w1 + w2)).epsilon(1e-14));
    CHECK(r.beta == Approx(2 * 0.01 / (w1 + w2)).epsilon(1e-14));
    CHECK(r.zeta(w1) == Approx(0.01).epsilon(1e-14));
    CHECK(r.zeta(w2) == Approx(0.01).epsilon(1e-14));
    // Between the two frequencies less damped, outside more (the curve's minimum at sqrt(alpha / beta)).
    CHECK(r.zeta(std::sqrt(w1 * w2)) < 0.01);
    CHECK(r.zeta(0.5 * w1) > 0.01);
    CHECK(r.zeta(2 * w2) > 0.01);
    // The modal coefficient is Phi^T (alpha M + beta K) Phi = alpha + beta w^2 = 2 zeta(w) w.
    CHECK(r.coefficient(w1 * w1) == Approx(2 * 0.01 * w1).epsilon(1e-14));
    CHECK(d.source.starts_with("[damping] rayleigh: zeta = 0.01 at 20 Hz and 200 Hz: alpha = "));

    const DampingSpec ab = damping_of("rayleigh = { alpha = 0.5, beta = 2e-5 }\n");
    CHECK(ab.rayleigh->alpha == 0.5);
    CHECK(ab.rayleigh->beta == 2e-5);
    CHECK(damping_of("rayleigh = { beta = 2e-5 }\n").rayleigh->alpha == 0.0);
    // The ratio keys and rayleigh are alternatives for the base.
    CHECK_FALSE(damping_of("ratio = 0.01\n").rayleigh);
}

TEST_CASE("Ratios per mode family and per mode sit on top of the base", "[response][scene]") {
    const DampingSpec d = damping_of("ratio = 0.01\nbending = 0.015\ntorsion = 0.03\n"
                                     "modes = [{ mode = 1, ratio = 0.02 }, { mode = 4, ratio = 0.005 }]\n");
    CHECK(d.ratio == 0.01);
    REQUIRE(d.families.size() == 2);
    CHECK(d.families[0].family == "bending");
    CHECK(d.families[0].ratio == 0.015);
    CHECK(d.families[1].family == "torsion");
    REQUIRE(d.modes.size() == 2);
    CHECK(d.modes[0].mode == 1);
    CHECK(d.modes[0].ratio == 0.02);
    CHECK(d.modes[1].mode == 4);
    // Where the mode number stands, for the run's check against the modes at rest.
    CHECK(d.modes[0].where == "cases/x.toml:16:19: [damping.modes #1]");
    // The same as an array of tables.
    const DampingSpec t = damping_of("log_decrement = 0.06\n[[damping.modes]]\nmode = 3\nratio = 0.02\n");
    REQUIRE(t.modes.size() == 1);
    CHECK(t.modes[0].mode == 3);
    // With Rayleigh as the base.
    CHECK(damping_of("rayleigh = { alpha = 0.5 }\nbending = 0.02\n").families.size() == 1);
}

TEST_CASE("[damping] Rayleigh, family and mode mistakes are refused with the key, the place and what is expected",
          "[response][scene]") {
    CHECK(error_with("ratio = 0.01\nrayleigh = { alpha = 0.5 }\n")
              .starts_with("cases/x.toml:14:12: [damping] rayleigh = {...} and [damping] ratio = 0.01 are "
                           "both given; expected exactly one of"));
    CHECK(error_with("bending = 0.02\n").starts_with("cases/x.toml:12:1: [damping] gives no damping for the modes it "
                                                     "does not name; expected exactly one of"));
    CHECK(error_with("rayleigh = { }\n").starts_with("cases/x.toml:13:12: [damping.rayleigh] gives no damping; "
                                                     "expected either alpha and beta"));
    CHECK(error_with("rayleigh = { alpha = 0.5, zeta = 0.01 }\n")
              .starts_with("cases/x.toml:13:34: [damping.rayleigh] mixes alpha/beta with zeta/frequencies"));
    CHECK(error_with("rayleigh = { alpha = 0, beta = 0 }\n")
              .starts_with("cases/x.toml:13:22: [damping.rayleigh] alpha and beta are both 0: no damping"));
    CHECK(error_with("rayleigh = { alpha = -1 }\n") == "cases/x.toml:13:22: [damping.rayleigh] alpha = -1 must be zero or positive");
    CHECK(error_with("rayleigh = { zeta = 0.01 }\n")
              .starts_with("cases/x.toml:13:12: [damping.rayleigh] frequencies is missing; expected two frequencies"));
    CHECK(error_with("rayleigh = { zeta = 0.01, frequencies = [\"20 Hz\"] }\n")
              .starts_with("cases/x.toml:13:41: [damping.rayleigh] frequencies = [\"20 Hz\"]: expected two frequencies"));
    CHECK(error_with("rayleigh = { zeta = 0.01, frequencies = [\"200 Hz\", \"20 Hz\"] }\n")
              .ends_with(": expected two different frequencies, the lower first"));
    CHECK(error_with("rayleigh = { zeta = 0.01, frequencies = [\"0 Hz\", \"20 Hz\"] }\n")
              .starts_with("cases/x.toml:13:42: [damping.rayleigh] frequencies = [\"0 Hz\", \"20 Hz\"]: a frequency must "
                           "be above 0"));
    CHECK(error_with("rayleigh = { zeta = 0.01, frequencies = [\"20 mm\", \"200 Hz\"] }\n")
              .starts_with("cases/x.toml:13:42: [damping.rayleigh] frequencies = [\"20 mm\", \"200 Hz\"]: unit 'mm' is a "
                           "length, expected a frequency"));
    CHECK(error_with("rayleigh = { zeta = 1.5, frequencies = [\"20 Hz\", \"200 Hz\"] }\n") ==
          "cases/x.toml:13:21: [damping.rayleigh] zeta = 1.5 is too large: expected at most 1");
    CHECK(error_with("ratio = 0.01\nbending = 0\n") == "cases/x.toml:14:11: [damping] bending = 0 must be positive");
    CHECK(error_with("ratio = 0.01\nbendng = 0.02\n")
              .starts_with("cases/x.toml:14:1: unknown key 'bendng' in [damping]; did you mean 'bending'?"));
    CHECK(error_with("ratio = 0.01\nmodes = [{ ratio = 0.02 }]\n")
              .starts_with("cases/x.toml:14:10: [damping.modes #1] mode is missing; expected the mode's number"));
    CHECK(error_with("ratio = 0.01\nmodes = [{ mode = 1 }]\n")
              .starts_with("cases/x.toml:14:10: [damping.modes #1] ratio is missing; expected"));
    CHECK(error_with("ratio = 0.01\nmodes = [{ mode = 0, ratio = 0.02 }]\n")
              .starts_with("cases/x.toml:14:19: [damping.modes #1] mode = 0 is out of range; expected 1 to"));
    CHECK(error_with("ratio = 0.01\nmodes = [{ mode = 2, ratio = 0.02 }, { mode = 2, ratio = 0.03 }]\n") ==
          "cases/x.toml:14:47: [damping.modes #2] mode = 2 is given twice; expected one ratio per mode");
    CHECK(error_with("ratio = 0.01\nmodes = [{ mode = 1, ratio = 0.02, zeta = 0.1 }]\n")
              .starts_with("cases/x.toml:14:36: unknown key 'zeta' in [damping.modes #1]"));
    CHECK(error_with("ratio = 0.01\nmodes = [1, 2]\n")
              .starts_with("cases/x.toml:14:9: [damping] modes = [1, 2]: expected tables"));
}

TEST_CASE("`check` describes the damping the forced response will use", "[response][scene]") {
    const ResponseCase c = parse_response_case_text(
        kRoll + "[damping]\nrayleigh = { zeta = 0.01, frequencies = [\"20 Hz\", \"200 Hz\"] }\nbending = 0.02\n"
                "modes = [{ mode = 1, ratio = 0.005 }]\n" + kRest,
        "cases/x.toml");
    const std::string text = describe_response(*c.response);
    CHECK(text.find("damping of every mode not named below: [damping] rayleigh: zeta = 0.01 at 20 Hz and 200 Hz") !=
          std::string::npos);
    CHECK(text.find("damping of every bending mode: zeta = 0.02") != std::string::npos);
    CHECK(text.find("damping of mode 1 at rest (shared by a degenerate partner): zeta = 0.005") != std::string::npos);
    CHECK(text.find("amplitude limit: 0.005 m at mid-span") != std::string::npos);
}

TEST_CASE("[damping] loss factors: for every part and per part, alone or over a viscous base", "[damping][scene]") {
    const DampingSpec alone = damping_of("loss_factor = 0.03\n");
    CHECK(alone.loss_factor == 0.03);
    CHECK(alone.ratio == 0.0);  // no viscous base: the loss factors are all the damping
    CHECK(!alone.rayleigh);
    CHECK(alone.source == "[damping] no viscous damping: the loss factors alone");
    const DampingSpec both = damping_of("ratio = 0.01\nloss_factor = 0.02\nloss_factors = { core = 0.04, chucks = 0 }\n");
    CHECK(both.ratio == 0.01);
    CHECK(both.loss_factor == 0.02);
    REQUIRE(both.part_loss_factors.size() == 2);
    CHECK(both.part_loss_factors.at("core") == 0.04);
    CHECK(both.part_loss_factors.at("chucks") == 0.0);
    const StructuralDamping effect{both.loss_factor, both.part_loss_factors};
    CHECK(effect.of("core") == 0.04);
    CHECK(effect.of("rest_paper") == 0.02);  // the base
    CHECK(effect.of("chuck_left") == 0.0);   // a chuck's mesh part takes the chucks' key
    // Per part alone, as a table of its own.
    CHECK(damping_of("[damping.loss_factors]\nrest_paper = 0.05\n").part_loss_factors.at("rest_paper") == 0.05);
    CHECK_FALSE(damping_of("ratio = 0.01\n").loss_factor > 0);
    // One wording for check's echo, the response's summary and its notes: every given value, in the file's units.
    CHECK(loss_factor_words(both) == "loss factor 0.02 (every part); chucks 0; core 0.04");
    CHECK(describe_damping(both).find("structural damping (stiffness K_p (1 + i eta_p)): loss factor 0.02 (every part); "
                                      "chucks 0; core 0.04\n") != std::string::npos);
    CHECK(loss_factor_words(damping_of("ratio = 0.01\n")).empty());  // none given: no words
}

TEST_CASE("[damping] loss factor mistakes are refused with the key, the place and what is expected", "[damping][scene]") {
    CHECK(error_with("loss_factor = -0.1\n") == "cases/x.toml:13:15: [damping] loss_factor = -0.1 must be positive");
    CHECK(error_with("loss_factor = 0\n") == "cases/x.toml:13:15: [damping] loss_factor = 0 must be positive");
    CHECK(error_with("loss_factor = 1.5\n") == "cases/x.toml:13:15: [damping] loss_factor = 1.5 is too large: expected at most 1");
    CHECK(error_with("loss_factors = { core = -0.01 }\n")
              .starts_with("cases/x.toml:13:25: [damping.loss_factors] core = -0.01 must be zero or positive"));
    CHECK(error_with("loss_factors = { core = 2 }\n")
              .starts_with("cases/x.toml:13:25: [damping.loss_factors] core = 2 is too large: expected at most 1"));
    CHECK(error_with("loss_factors = { shaft = 0.01 }\n")
              .starts_with("cases/x.toml:13:18: unknown key 'shaft' in [damping.loss_factors]; expected one of core, rest_paper, chucks"));
    // A per-part table that damps nothing is no damping.
    CHECK(error_with("loss_factors = { core = 0 }\n")
              .starts_with("cases/x.toml:12:1: [damping] gives no damping for the modes it does not name; expected "
                           "exactly one of"));
}
