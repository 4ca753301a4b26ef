// The verdict over the unwind (analyses/limits) against the standalone
// analyses it drives, on case 13's rotogravure rest roll at the beam level:
// every criterion is the number `response`, `campbell`, `run` and König's
// formula give on the same scene and diameter; the roll change is the hand
// interpolation of the governing speeds; the band holds the point value and
// narrows with an input's range; the knife edge of case 13 is flagged.
#include "analyses/campbell/campbell.hpp"
#include "analyses/fit/fit.hpp"
#include "analyses/limits/limits.hpp"
#include "analyses/limits/limits_band.hpp"
#include "analyses/response/response.hpp"
#include "analyses/run/run.hpp"
#include "beam/beam_model.hpp"
#include "beam/rotating_modes.hpp"
#include "common/error.hpp"
#include "modes/tracking.hpp"
#include "scene/limits_spec.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/toml_text.hpp"
#include "scene/traction_case.hpp"
#include "traction/traction_sweep.hpp"

#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace coremodal;

namespace {

const std::string kCase13 = std::string(COREMODAL_SOURCE_DIR) + "/cases/13-rest-roll-response-150x15.8-4320.toml";

std::string case13_text() { return read_input_file(kCase13, "case file"); }

// Case 13 with its rest paper `thickness` thick: the scene the verdict builds
// at that diameter, read by the case reader instead.
ResponseCase case13_with_paper(const std::string& thickness) {
    std::string text = case13_text();
    const std::string from = "thickness = \"10 mm\"";
    text.replace(text.find(from), from.size(), "thickness = \"" + thickness + "\"");
    return parse_response_case_text(text, kCase13);
}

// Case 12's core clamped over 70 mm with 10 mm of rest paper (Dp 126 mm), a
// 0.5 mm bow and 1 % damping, at the beam level: a few hundred unknowns.
LimitsCase small_roll() {
    const std::string& text = testing::kBowedTesterRoll;
    return parse_limits_case_text(text, "small.toml");
}

LimitsRequest diameters(double largest, double smallest, int points, bool band) {
    LimitsRequest r;
    r.spec.largest_diameter_m = largest, r.spec.smallest_diameter_m = smallest;
    r.spec.points = points, r.spec.band = band;
    return r;
}

}  // namespace

// [long] here and below: 3-8 s each at -O2, over 1,000 s for two of them
// under the sanitizers on a loaded machine (scripts/sanitize.sh leaves [long]
// out of CI); the band, refusal and traction tests run the verdict there.
TEST_CASE(
    "Each criterion of the verdict is the standalone analysis' number on "
    "the same scene and diameter",
    "[limits][long]") {
    const LimitsCase c = parse_limits_case(kCase13);
    REQUIRE(c.response);
    const LimitsResult r = verdict(c.scene, c.response, diameters(0.2021, 0.1921, 2, false));
    REQUIRE(r.points.size() == 2);
    for (int i = 0; i < 2; ++i) {
        const LimitsPoint& p = r.points[i];
        // The case's roll, then the case with 5 mm of paper (Dp 192.1 mm), read
        // from its file.
        const ResponseCase standalone = i == 0 ? parse_response_case(kCase13) : case13_with_paper("5 mm");
        CHECK(p.diameter_m == Approx(roll_outer_diameter(standalone.scene)).epsilon(1e-12));
        const ResponseResult response = run_forced_response(standalone.scene, *standalone.response);
        CHECK(p.f1_hz == Approx(response.speeds_at_rest.f1_hz).epsilon(1e-10));
        CHECK(p.at(Criterion::i5_low).web_speed_m_s ==
              Approx(response.speeds_at_rest.safe[0].v_safe_m_s).epsilon(1e-10));
        CHECK(p.at(Criterion::i5_high).web_speed_m_s ==
              Approx(response.speeds_at_rest.safe[1].v_safe_m_s).epsilon(1e-10));
        const KoenigSpeeds& k = *response.speeds_at_rest.koenig;
        CHECK(p.at(Criterion::koenig).web_speed_m_s ==
              Approx(k.v_krit_large_core_m_s.value_or(k.speed.v_krit_m_s)).epsilon(1e-10));
        // The amplitude limit: both refined by bisection on their own grids
        // (response_sweep.hpp).
        // At 192.1 mm the resonance stays below +-5 mm in both: no limit reached.
        CHECK(p.at(Criterion::amplitude).given == response.safe.reached);
        if (response.safe.reached)
            CHECK(p.at(Criterion::amplitude).web_speed_m_s == Approx(response.safe.web_speed_m_s).epsilon(1e-3));
        // The Campbell sweep on another grid of speeds: the crossings are refined
        // to 1e-6.
        RotationSpec rotation;
        rotation.speeds_hz = {0, 10, 20, 30, 40};
        rotation.from_web_speed = true;
        const CampbellResult campbell = run_campbell(standalone.scene, rotation);
        const WhirlCrossing* first = campbell.first_order_one();
        REQUIRE(first);
        const Criterion which = first->whirl == Whirl::forward ? Criterion::order1_forward : Criterion::order1_backward;
        CHECK(p.at(which).web_speed_m_s == Approx(first->web_speed_m_s).epsilon(1e-5));
        // k as `run` computes it on the scene at its level.
        const ChuckFactor factor = chuck_factor(standalone.scene, response.speeds_at_rest.f1_hz, true);
        REQUIRE(p.chuck_factor);
        CHECK(*p.chuck_factor == Approx(factor.chuck_factor).epsilon(1e-10));
    }
    // I-5 at 0.7 is below Koenig, the critical speeds and the amplitude limit
    // here (docs/how-to/limits.md).
    CHECK(r.points[0].governing == static_cast<int>(Criterion::i5_low));
    CHECK(r.verdict.governed_by == criterion_name(Criterion::i5_low));
}

TEST_CASE(
    "The roll change is where the governing speed crosses the target, "
    "interpolated between diameters",
    "[limits][long]") {
    const LimitsCase c = parse_limits_case(kCase13);
    LimitsRequest request = diameters(0.2021, 0.1921, 2, false);
    const LimitsResult plain = verdict(c.scene, c.response, request);
    REQUIRE(plain.points.size() == 2);  // no midpoint: the safe speed moves by less than kFastChange
    const double va = plain.points[0].safe_m_s, vb = plain.points[1].safe_m_s;
    const double da = plain.points[0].diameter_m, db = plain.points[1].diameter_m;
    REQUIRE(va != vb);
    // A target a quarter of the way from the one to the other: the change (or
    // the refusal) a hand calculation gives.
    request.target_web_speed_m_s = va + 0.25 * (vb - va);
    const LimitsResult r = verdict(c.scene, c.response, request);
    REQUIRE(r.change);
    if (va > vb) {  // the safe speed falls as the roll unwinds: change at a
                    // quarter of the way
        CHECK(r.change->needed);
        CHECK_FALSE(r.change->never_safe);
        CHECK(r.change->diameter_m == Approx(da + 0.25 * (db - da)).epsilon(1e-9));
        CHECK(r.change->margin_m_s == Approx(va - *request.target_web_speed_m_s).epsilon(1e-9));
    } else {  // it rises: the full roll is the slowest, already below the target
        CHECK(r.change->never_safe);
        CHECK(r.change->diameter_m == Approx(da));
    }
    // The verdict quotes the lowest safe speed down to the change.
    CHECK(r.verdict.speed_m_s <= std::max(va, vb));
    CHECK(verdict_line(r).rfind("safe up to ", 0) == 0);
}

TEST_CASE(
    "The band holds every point value and narrows when an input's range "
    "narrows",
    "[limits][band]") {
    const LimitsCase c = small_roll();
    const LimitsRequest wide = diameters(0.126, 0.126, 1, true);
    const LimitsResult r = verdict(c.scene, c.response, wide);
    REQUIRE(r.points.size() == 1);
    const LimitsPoint& p = r.points[0];
    CHECK(p.safe_low_m_s <= p.safe_m_s);
    CHECK(p.safe_m_s <= p.safe_high_m_s);
    CHECK(p.safe_low_m_s < p.safe_high_m_s);  // E_z moves f1
    for (const CriterionSpeed& s : p.criteria) {
        if (!s.given) continue;
        INFO(criterion_name(s.criterion));
        CHECK(s.band_low_m_s <= s.web_speed_m_s);
        CHECK(s.web_speed_m_s <= s.band_high_m_s);
    }
    // The verdict quotes the conservative end.
    CHECK(r.verdict.speed_m_s == p.safe_low_m_s);
    // Every input at a tenth of its spread about the nominal (a measurement):
    // every band inside the wide one, the safe speed's narrower.
    LimitsRequest narrow = wide;
    ResponseSetup base = *c.response;
    std::vector<UncertainInput> inputs = uncertain_inputs(c.scene, base);
    for (UncertainInput& i : inputs) {
        const double nominal = i.name == "damping ratio" ? base.damping.ratio
                               : i.name == "bow"         ? base.excitation.bow_m
                                                         : 1.0;
        i.low = nominal + 0.1 * (i.low - nominal), i.high = nominal + 0.1 * (i.high - nominal);
    }
    narrow.inputs = inputs;
    const LimitsResult n = verdict(c.scene, c.response, narrow);
    const LimitsPoint& q = n.points[0];
    CHECK(q.safe_m_s == Approx(p.safe_m_s).epsilon(1e-12));
    CHECK(q.safe_low_m_s >= p.safe_low_m_s);
    CHECK(q.safe_high_m_s <= p.safe_high_m_s);
    CHECK(q.safe_high_m_s - q.safe_low_m_s < 0.5 * (p.safe_high_m_s - p.safe_low_m_s));
    for (size_t i = 0; i < q.criteria.size(); ++i) {
        if (!q.criteria[i].given) continue;
        INFO(criterion_name(q.criteria[i].criterion));
        CHECK(q.criteria[i].band_low_m_s >= p.criteria[i].band_low_m_s - 1e-9);
        CHECK(q.criteria[i].band_high_m_s <= p.criteria[i].band_high_m_s + 1e-9);
    }
}

TEST_CASE(
    "Case 13 as shipped sits on a knife edge: its amplitude limit is 0.2 "
    "% below the resonance peak",
    "[limits][long]") {
    const LimitsCase c = parse_limits_case(kCase13);
    const LimitsResult r = verdict(c.scene, c.response, diameters(0.2021, 0.2021, 1, false));
    bool knife = false;
    for (const std::string& w : r.warnings) knife = knife || w.rfind("knife edge", 0) == 0;
    CHECK(knife);
    // With twice the damping the peak halves below the limit (docs/how-to/response.md):
    // no knife edge.
    ResponseSetup damped = *c.response;
    damped.damping.ratio = 0.02;
    const LimitsResult d = verdict(c.scene, damped, diameters(0.2021, 0.2021, 1, false));
    for (const std::string& w : d.warnings) CHECK(w.rfind("knife edge", 0) != 0);
}

TEST_CASE("The verdict refuses what it cannot carry before any work, naming the key", "[limits]") {
    const LimitsCase c = parse_limits_case(kCase13);
    Scene coupled = c.scene;
    coupled.model = ModelChoice::coupled;
    CHECK_THROWS_WITH(
        require_limits_scene(coupled, {}),
        Catch::Contains("model = \"coupled\"") && Catch::Contains("expected model = \"beam\" or \"harmonic\""));
    Scene free = c.scene;
    free.supports = {};
    CHECK_THROWS_WITH(require_limits_scene(free, {}), Catch::Contains("[supports]"));
    LimitsRequest negative;
    negative.target_web_speed_m_s = -3;
    CHECK_THROWS_WITH(require_limits_scene(c.scene, negative),
                      Catch::Contains("--speed") && Catch::Contains("above 0"));
}

TEST_CASE("A [traction] roller joins the verdict as the web's slip speed, the standalone traction number",
          "[limits][traction]") {
    const LimitsCase c = small_roll();
    const std::string case19 = std::string(COREMODAL_SOURCE_DIR) + "/cases/19-grooved-idler-traction.toml";
    const std::optional<TractionCase> roller = read_traction_case(case19);
    REQUIRE(roller);
    const double d = roll_outer_diameter(c.scene);
    SECTION("without a roller the line is there, not given, and the verdict is the roll's own") {
        const LimitsResult r = verdict(c.scene, c.response, diameters(d, d, 1, false));
        REQUIRE(r.points.size() == 1);
        CHECK_FALSE(r.points[0].at(Criterion::traction).given);
        CHECK(r.points[0].governing != static_cast<int>(Criterion::traction));
    }
    SECTION("the zero-traction speed is `coremodal traction`'s, the same at every diameter") {
        LimitsRequest request = diameters(d, c.scene.core.outer_diameter, 2, false);
        TractionSpec spec = roller->spec;
        spec.tension_difference.reset();
        request.traction = traction_slip_criterion(spec);
        const LimitsResult r = verdict(c.scene, c.response, request);
        const double standalone = run_traction_sweep(spec).zero_traction_speed;  // what `traction` reports
        for (const LimitsPoint& p : r.points) {
            CHECK(p.at(Criterion::traction).given);
            CHECK(p.at(Criterion::traction).web_speed_m_s == Approx(standalone).epsilon(1e-12));
        }
    }
    SECTION("a roller that slips first governs, band and all") {
        // 99 % of what the roller carries at rest, the capstan limit
        // T0 (1 - exp(-f theta)): it slips at a crawl, below every roll speed.
        TractionSpec spec = roller->spec;
        const double at_rest = spec.tension * (1 - std::exp(-spec.friction * spec.wrap));
        spec.tension_difference = 0.99 * at_rest;
        LimitsRequest request = diameters(d, d, 1, true);
        request.traction = traction_slip_criterion(spec);
        const double slip = slip_speed(spec, *spec.tension_difference);
        REQUIRE(slip > 0);
        const LimitsResult r = verdict(c.scene, c.response, request);
        const LimitsPoint& p = r.points.at(0);
        REQUIRE(p.at(Criterion::i5_low).given);
        REQUIRE(slip < p.at(Criterion::i5_low).web_speed_m_s);
        CHECK(p.governing == static_cast<int>(Criterion::traction));
        CHECK(p.safe_m_s == Approx(slip).epsilon(1e-12));
        CHECK(p.safe_low_m_s == Approx(slip).epsilon(1e-12));  // no input of the roll's band moves the roller
        CHECK(r.verdict.governed_by == std::string("web slip (traction)"));
    }
}

TEST_CASE("The pencils' critical speeds are the Campbell sweep's refined crossings", "[limits][speed][long]") {
    // Case 13 at the beam level: its bending planes are alike, so the verdict
    // takes the order-1 and order-2 crossings from the plane problem's pencils
    // (beam/rotating_modes.hpp) instead of the sweep; the sweep refines its
    // crossings to 1e-6 of the speed (kCrossingSpeedTolerance).
    const LimitsCase c = parse_limits_case(kCase13);
    const BeamModelResult beam = solve_beam_model(c.scene);
    const double top_hz = 40;
    const std::optional<std::vector<PlaneCrossing>> pencil =
        plane_critical_speeds(beam.network, beam.lambda_scale, {1, 2}, top_hz);
    REQUIRE(pencil);
    RotationSpec rotation;
    for (int i = 0; i <= 20; ++i) rotation.speeds_hz.push_back(top_hz * i / 20);
    rotation.excitation_orders = {1, 2};
    const CampbellResult campbell = run_campbell(c.scene, rotation);
    for (int order : {1, 2})
        for (Whirl whirl : {Whirl::forward, Whirl::backward}) {
            INFO("order " << order << " " << whirl_name(whirl));
            const auto same = [&](const auto& x) { return x.order == order && x.whirl == whirl; };
            const auto p = std::find_if(pencil->begin(), pencil->end(), same);
            const auto s = std::find_if(campbell.critical.begin(), campbell.critical.end(), same);
            REQUIRE(p != pencil->end());
            REQUIRE(s != campbell.critical.end());
            CHECK(p->speed_hz == Approx(s->speed_hz).epsilon(2 * kCrossingSpeedTolerance));
            CHECK(label_text(p->label) == label_text(s->label));
        }
}

TEST_CASE("A forced response that leaves its checks to the caller gives the checked run's numbers",
          "[limits][speed]") {
    // ResponseChecking::none keeps only the modes up to the cutoff (the
    // network's Krylov solver) and the static part of the others as K^-1 f less
    // the kept modes' part: the same truncated sum as the complete basis gives.
    const ResponseCase c = parse_response_case(kCase13);
    const ResponseResult full = run_forced_response(c.scene, *c.response);
    const ResponseResult fast = run_forced_response(c.scene, *c.response, {}, ResponseChecking::none);
    CHECK(full.checks.speeds_checked > 0);
    CHECK(fast.checks.speeds_checked == 0);
    CHECK(fast.checks.n_modes_used == full.checks.n_modes_used);
    REQUIRE(fast.points.size() == full.points.size());
    for (size_t i = 0; i < full.points.size(); ++i)
        CHECK(fast.points[i].probes[0].total_m == Approx(full.points[i].probes[0].total_m).epsilon(1e-8));
    REQUIRE(fast.safe.reached == full.safe.reached);
    CHECK(fast.safe.web_speed_m_s == Approx(full.safe.web_speed_m_s).epsilon(1e-8));
    REQUIRE(fast.peaks.size() == full.peaks.size());
    for (size_t i = 0; i < full.peaks.size(); ++i)
        CHECK(fast.peaks[i].amplitude_m == Approx(full.peaks[i].amplitude_m).epsilon(1e-8));
}

TEST_CASE("A measured first resonance narrows the band through fit, around the fitted point value",
          "[limits][band][fit][long]") {
    // Case 16's measurements file (cases/16-limits-measured-f1.toml): the first
    // resonance of the full roll in its stand; the fit sets the chucks' contact
    // stiffness, the verdict at the full roll runs on the fitted case.
    const std::string measurements = std::string(COREMODAL_SOURCE_DIR) + "/cases/16-limits-measured-f1.toml";
    const std::string case16 = std::string(COREMODAL_SOURCE_DIR) + "/cases/16-limits-rotogravure-150x15.8-4320.toml";
    const FitOutcome fit = run_fit(read_fit_input(measurements));
    REQUIRE(fit.converged);
    REQUIRE(fit.cases.size() == 1);
    REQUIRE(fit.parameters.at(0).uncertainty);
    CHECK(fit.measurements.at(0).model_hz == Approx(21.2).margin(0.05));  // the fit reproduces the measurement
    const LimitsCase fitted = parse_limits_case_text(fit.cases[0].calibrated_text, case16);
    const LimitsCase original = parse_limits_case(case16);
    const double d = roll_outer_diameter(original.scene);
    const LimitsRequest wide = diameters(d, d, 1, true);
    LimitsRequest narrow = wide;
    narrow.fit = fit, narrow.fit_file = measurements;
    const LimitsResult before = verdict(original.scene, original.response, wide);
    const LimitsResult after = verdict(fitted.scene, fitted.response, narrow);
    const LimitsPoint &p = before.points.at(0), &q = after.points.at(0);
    // The model now has the measured f1.
    CHECK(q.f1_hz == Approx(fit.measurements[0].model_hz).epsilon(1e-6));
    // The contact's range is the fit's, narrower than x1/3 - x3.
    const auto contact = std::find_if(after.inputs.begin(), after.inputs.end(),
                                      [](const UncertainInput& i) { return i.name == "chuck contact stiffness"; });
    REQUIRE(contact != after.inputs.end());
    CHECK(contact->low > 1 / 3.0);
    CHECK(contact->high < 3.0);
    CHECK(contact->source.rfind("fitted: ", 0) == 0);
    // The band holds the point value and is narrower than before.
    CHECK(q.safe_low_m_s <= q.safe_m_s);
    CHECK(q.safe_m_s <= q.safe_high_m_s);
    CHECK(q.safe_high_m_s - q.safe_low_m_s < p.safe_high_m_s - p.safe_low_m_s);
    for (const CriterionSpeed& s : q.criteria) {
        if (!s.given) continue;
        INFO(criterion_name(s.criterion));
        CHECK(s.band_low_m_s <= s.web_speed_m_s);
        CHECK(s.web_speed_m_s <= s.band_high_m_s);
    }
}

TEST_CASE("run's verdict line is the limits verdict at the case's roll, at the beam level", "[limits]") {
    const LimitsCase c = parse_limits_case(kCase13);
    const std::string line = stand_verdict_line(kCase13);
    REQUIRE(line.find("safe up to ") != std::string::npos);
    LimitsRequest request = diameters(roll_outer_diameter(c.scene), roll_outer_diameter(c.scene), 1, false);
    request.check_response = false;
    const LimitsResult r = verdict(c.scene, c.response, request);
    CHECK(line.substr(line.find("safe up to ")) == verdict_line(r));
    CHECK_FALSE(r.checks);  // left to `limits` and `response`
    // A free scene has no stand: no line.
    const std::string free_case = std::string(COREMODAL_SOURCE_DIR) + "/cases/01-iso-free-free-76x15.toml";
    CHECK(stand_verdict_line(free_case).empty());
}

TEST_CASE("At the harmonic level the response's n = 1 crossings are the Campbell sweep's refined crossings",
          "[limits][speed][long]") {
    // The verdict takes the harmonic level's critical speeds from the forced
    // response's own n = 1 model in its kept modes (ModalResponse::
    // synchronous_crossings) instead of a Campbell sweep over every wave
    // number. The sweep (RotatingHarmonics: the full problem's residuals,
    // crossings refined to 1e-6) is the independent truth; the kept modes
    // reach 3x the top speed, so what is left out shifts a crossing by its
    // gyroscopic coupling to modes far above: 0.12 % (order 1) here, 0.055 %
    // on case 16; a band of the verdict is several per cent wide.
    constexpr double kAgreement = 2e-3;
    LimitsCase c = small_roll();
    c.scene.model = ModelChoice::harmonic;
    apply_mesh_level(c.scene, "coarse");
    ResponseSetup setup = *c.response;
    const double top_hz = 60;  // above f1 (~45 Hz) and the order-2 crossing of the first bending mode
    setup.response.from_web_speed = false;
    setup.response.speeds_hz.clear();
    for (int i = 1; i <= 20; ++i) setup.response.speeds_hz.push_back(top_hz * i / 20);
    const ResponseResult response = run_forced_response(c.scene, setup, {}, ResponseChecking::none);
    RotationSpec rotation;
    for (int i = 0; i <= 12; ++i) rotation.speeds_hz.push_back(top_hz * i / 12);
    rotation.excitation_orders = {1, 2};
    const CampbellResult campbell = run_campbell(c.scene, rotation);
    int compared = 0;
    for (int order : {1, 2})
        for (Whirl whirl : {Whirl::forward, Whirl::backward}) {
            INFO("order " << order << " " << whirl_name(whirl));
            const auto mine = std::find_if(response.crossings.begin(), response.crossings.end(), [&](const auto& x) {
                return x.order == order && x.forward == (whirl == Whirl::forward);
            });
            const auto swept = std::find_if(campbell.critical.begin(), campbell.critical.end(), [&](const auto& x) {
                return x.order == order && x.whirl == whirl && x.label.type == "bending";
            });
            REQUIRE(swept != campbell.critical.end());
            REQUIRE(mine != response.crossings.end());
            CHECK(mine->speed_hz == Approx(swept->speed_hz).epsilon(kAgreement));
            CHECK(mine->mode.type == "bending");
            ++compared;
        }
    CHECK(compared == 4);
}

TEST_CASE("The verdict's light check compares the truncated sum with the sparse direct solve at every check speed",
          "[limits][speed]") {
    // ResponseChecking::light at the beam level (the verdict's one check):
    // the modes up to the cutoff only (no dense eigensolve of every mode) and
    // the truncated sum against the sparse direct solve at every check speed.
    // That difference is the full check's truncated-against-complete one but
    // for the damping of the modes left out (undamped in the direct solve as
    // in the sum's static part): a 1/(1 + (2 zeta w/w_j)^2) effect, 0.04 % of
    // it here; the numbers are the full run's (the same truncated sum).
    const LimitsCase c = small_roll();
    const ResponseResult full = run_forced_response(c.scene, *c.response);
    const ResponseResult light = run_forced_response(c.scene, *c.response, {}, ResponseChecking::light);
    CHECK(light.checks.speeds_checked == full.checks.speeds_checked);
    CHECK_FALSE(light.checks.complete_basis);
    CHECK(light.checks.direct_speeds_checked == light.checks.speeds_checked);
    CHECK(light.checks.truncation_max_relative == Approx(full.checks.truncation_max_relative).epsilon(1e-2));
    CHECK(light.checks.truncation_max_relative > 0);
    REQUIRE(light.safe.reached == full.safe.reached);
    CHECK(light.safe.web_speed_m_s == Approx(full.safe.web_speed_m_s).epsilon(1e-8));
}
