// The width half of the core-selection chart: the candidate's beam is
// calibrated to I-7 with the stand's chuck factor (checked against I-7 by
// hand), and select's width limit is the root of the limits verdict (the
// verdict's own speed at a known width gives that width back).
#include "analyses/limits/limits.hpp"
#include "analyses/limits/limits_band.hpp"
#include "analyses/select/rest_roll_limit.hpp"
#include "beam/beam_model.hpp"
#include "beam/speeds.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace coremodal;

namespace {

// One grade given by fitted values in a news-like stand.
const std::string kOneCandidate = R"(
[selection]
paper_density = "750 kg/m^3"
rest_paper_modulus = "5 GPa"
rest_paper_density = "1350 kg/m^3"
[[selection.core]]
name = "thin"
inner_diameter = "76 mm"
outer_diameter = "100 mm"
flexural_modulus = "4 GPa"
density = "700 kg/m^3"
b0 = "20 kN"
b1 = -0.1
s_log = 0.05
test_chuck_length = "100 mm"
[[selection.stand]]
name = "news"
chuck_length = "110 mm"
chuck_factor = 0.85
rest_roll_diameter = "120 mm"
roll_diameter = "1000 mm"
)";

double first_bending(const Scene& scene) {
    for (const BeamMode& m : solve_beam_model(scene).modes)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}

}  // namespace

TEST_CASE("the candidate's beam is calibrated to I-7 with the stand's chuck factor", "[selection][limits]") {
    const SelectionScene s = read_selection_text(kOneCandidate, "s.toml");
    const double width = 1.8;
    const CandidateScene c = candidate_scene(s.cores[0], s.stands[0], s, width);
    // I-7 by hand: k (beta1 L)^2/(2 pi) / L^2 sqrt(EI / rho A), L = width - 2 li, li = 55 mm;
    // (beta1 L)^2 = 4.7300407^2, printed 22.373 in I-7 (cos x cosh x = 1).
    const double pi = std::numbers::pi;
    const double di = 0.076, d0 = 0.100, dp = 0.120;
    const double ei =
        4e9 * pi / 64 * (std::pow(d0, 4) - std::pow(di, 4)) + 5e9 * pi / 64 * (std::pow(dp, 4) - std::pow(d0, 4));
    const double rho_a = 700 * pi / 4 * (d0 * d0 - di * di) + 1350 * pi / 4 * (dp * dp - d0 * d0);
    const double span = width - 2 * 0.055;
    const double i7 = 0.85 * std::pow(4.730040744862704, 2) / (2 * pi) / (span * span) * std::sqrt(ei / rho_a);
    CHECK(c.target_f1_hz == Approx(i7).epsilon(1e-12));
    CHECK(first_bending(c.scene) == Approx(i7).epsilon(2 * kCalibrationTolerance));
    // A rigid clamp is stiffer than the stand's chucks (k < 1): the calibration softens.
    CHECK(c.stiffness_factor < 1.0);
    CHECK(c.scene.core.material.E_z == Approx(4e9 * c.stiffness_factor));
}

TEST_CASE("select's width limit at the verdict's speed is the verdict's width", "[selection][limits]") {
    const SelectionScene s = read_selection_text(kOneCandidate, "s.toml");
    const CoreGrade& core = s.cores[0];
    const Stand& stand = s.stands[0];
    const double width = 1.8;
    // The limits verdict itself, called as `coremodal limits` would on the calibrated scene at one diameter,
    const CandidateScene c = candidate_scene(core, stand, s, width);
    LimitsRequest request;
    request.spec.largest_diameter_m = request.spec.smallest_diameter_m = stand.rest_roll_diameter;
    request.spec.band = false;
    const LimitsResult limits = verdict(c.scene, std::nullopt, request);
    // with König's formula on the section as given, as `coremodal limits` takes it on the real stand.
    std::vector<CriterionSpeed> criteria = limits.points.front().criteria;
    const std::optional<KoenigSpeeds> koenig = roll_speeds(c.as_given, limits.points.front().f1_hz, "").koenig;
    REQUIRE(koenig);
    criteria[static_cast<int>(Criterion::koenig)].web_speed_m_s = koenig->speed.v_krit_m_s;  // a 76 mm core
    const int lowest = lowest_limiting(criteria);
    REQUIRE(lowest >= 0);
    const double v = criteria[lowest].web_speed_m_s;
    // I-5 at 0.7 of the calibrated f1 is I-5 of I-7's f1.
    CHECK(criteria[static_cast<int>(Criterion::i5_low)].web_speed_m_s ==
          Approx(0.7 * std::numbers::pi * 0.120 * c.target_f1_hz).epsilon(1e-6));
    CHECK(rest_roll_verdict(core, stand, s, width, v).safe_speed_m_s == Approx(v).epsilon(1e-9));
    RestRollVerdict at_limit;
    const double found = max_width_for_speed(core, stand, s, v, &at_limit);
    CHECK(found == Approx(width).margin(kWidthTolerance));
    CHECK(rest_roll_verdict(core, stand, s, found, v).passes);
    CHECK_FALSE(rest_roll_verdict(core, stand, s, found + 2 * kWidthTolerance, v).passes);
    // The verdict adds criteria to I-5 with I-7's f1, never removes one: its width is at most I-7's.
    CHECK(found <= i7_max_width(core, stand, s, v) * (1 + kCalibrationTolerance) + kWidthTolerance);
}

TEST_CASE("with I-5 at 0.8 König's critical speed limits the width, as his formula says", "[selection][limits]") {
    SelectionScene s = read_selection_text(kOneCandidate, "s.toml");
    Stand& stand = s.stands[0];
    stand.safe_factor = 0.8;  // Ilomäki's upper factor: I-5 rises above König for this roll
    const CoreGrade& core = s.cores[0];
    RestRollVerdict at_limit;
    const double found = max_width_for_speed(core, stand, s, 15.0, &at_limit);
    REQUIRE(at_limit.governing == "Koenig K-1/K-2");
    // König's K-1/K-2 on the roll's own section over the span between the chucks'
    // inner ends (width - 2 x 110 mm), solved for 15 m/s by bisection.
    const RestRollSection section{0.076, 0.100, 0.120, 4e9, 700, 5e9, 1350};
    double lo = 0.5, hi = 5.0;
    while (hi - lo > 1e-7) {
        const double w = 0.5 * (lo + hi);
        (koenig_critical_speed(section, w - 0.22, kKoenigExperience).speed.v_krit_m_s >= 15.0 ? lo : hi) = w;
    }
    CHECK(found == Approx(lo).margin(kWidthTolerance));
    CHECK(found < i7_max_width(core, stand, s, 15.0) - 0.01);  // I-5 with I-7 alone allows more
}
