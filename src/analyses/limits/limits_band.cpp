#include "analyses/limits/limits_band.hpp"

#include "beam/speeds.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "models/choose.hpp"
#include "scene/rotation_spec.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace coremodal {
namespace {

// The ranges (docs/how-to/limits.md, "The band", has the same table with sources).
// Contact stiffness of the chuck's spring layer: uncertain by 3-5x
// (docs/theory/chucks.md, docs/reference/material-sources.md "Sensitivities"); x/3 .. x3.
constexpr double kContactFactor = 3.0;
// The core's E_z: no general spread was found (docs/reference/material-sources.md): the
// ISO 11093-8 value of the core in question. Assumed +-15 %.
constexpr double kCoreModulusSpread = 0.15;
// The stand's compliance (bearings, frame): Ilomaki names it ("the more the
// chucks and the machine frame are vibrating with the rest roll ... the lower
// the safe web speed") but gives no number; assumed x0.5 .. x2.
constexpr double kStandFactor = 2.0;
// The bow's lower end: a core half as bowed as given (straighter than the
// tolerance, as most are); the upper end Ilomaki's tolerance 0.5 mm/m.
constexpr double kBowLowFactor = 0.5;
// Running web tensions (Roisum, The Mechanics of Web Handling, TAPPI 1998).
constexpr double kWebTensionLow = 100.0, kWebTensionHigh = 1000.0;  // N/m

using Apply = std::function<void(Scene&, ResponseSetup&, double)>;

void scale_damping(ResponseSetup& s, double zeta) {
    const double factor = zeta / s.damping.ratio;
    s.damping.ratio = zeta;
    for (auto& f : s.damping.families) f.ratio = std::min(f.ratio * factor, 0.99);
    for (auto& m : s.damping.modes) m.ratio = std::min(m.ratio * factor, 0.99);
}

void scale_contact(Scene& s, double factor) {
    for (ChuckSpec& c : s.supports.chucks) {
        c.interface.normal_stiffness *= factor;
        c.interface.tangential_stiffness *= factor;
    }
}

void scale_stand(Scene& s, double factor) {
    for (ChuckSpec& c : s.supports.chucks) {
        BearingSpec& b = c.bearing;
        b.radial_stiffness *= factor, b.tilting_stiffness *= factor;
        if (b.frame_stiffness) *b.frame_stiffness *= factor;
    }
}

// How each input is set in a sample, by its name in uncertain_inputs.
Apply apply_of(const std::string& name) {
    if (name == "damping ratio") return [](Scene&, ResponseSetup& s, double v) { scale_damping(s, v); };
    if (name == "bow") return [](Scene&, ResponseSetup& s, double v) { s.excitation.bow_m = v; };
    if (name == "chuck contact stiffness") return [](Scene& s, ResponseSetup&, double v) { scale_contact(s, v); };
    if (name == "core E_z") return [](Scene& s, ResponseSetup&, double v) { s.core.material.E_z *= v; };
    if (name == "stand stiffness") return [](Scene& s, ResponseSetup&, double v) { scale_stand(s, v); };
    if (name == "web tension") return [](Scene& s, ResponseSetup&, double v) { s.web->tension = v; };
    COREMODAL_ASSERT(false);
    return {};
}

// An input that changes only the response's setup (its damping, its load),
// not K or M: its samples share the scene's model (run_forced_responses).
bool changes_setup_only(const std::string& name) { return name == "damping ratio" || name == "bow"; }

bool spring_chucks(const Scene& s) {
    return s.supports.kind == SupportKind::chucks && s.supports.chucks.at(0).interface.kind == InterfaceKind::spring;
}

bool elastic_stand(const Scene& s) {
    return s.supports.kind == SupportKind::chucks && std::any_of(s.supports.chucks.begin(), s.supports.chucks.end(),
                                                                 [](const ChuckSpec& c) { return !c.bearing.rigid; });
}

UncertainInput input(std::string name, std::string range, std::string source, double low, double high,
                     std::string what) {
    UncertainInput i;
    i.name = std::move(name), i.range = std::move(range), i.source = std::move(source);
    i.low = low, i.high = high, i.what = std::move(what);
    return i;
}

CriterionSpeed given(Criterion c, double v) {
    CriterionSpeed s;
    s.criterion = c, s.given = true, s.web_speed_m_s = v, s.band_low_m_s = s.band_high_m_s = v;
    return s;
}

CriterionSpeed missing(Criterion c, std::string why) {
    CriterionSpeed s;
    s.criterion = c, s.note = std::move(why);
    return s;
}

}  // namespace

std::vector<CriterionSpeed> criteria_of(const ResponseResult& response, const CriticalSpeeds& critical,
                                        double f1_ratio) {
    std::vector<CriterionSpeed> out;
    const RollSpeeds& speeds = response.speeds_at_rest;
    for (size_t i = 0; i < 2; ++i) {
        const Criterion c = i == 0 ? Criterion::i5_low : Criterion::i5_high;
        out.push_back(speeds.given() && speeds.safe.size() > i ? given(c, speeds.safe[i].v_safe_m_s)
                                                               : missing(c, speeds.not_given));
    }
    out[1].limits = false;  // 0.8 is above 0.7: reported beside it
    if (speeds.koenig)
        out.push_back(
            given(Criterion::koenig, speeds.koenig->v_krit_large_core_m_s.value_or(speeds.koenig->speed.v_krit_m_s)));
    else
        out.push_back(missing(Criterion::koenig, "no free span between two supports"));
    const auto crit = [&](Criterion c, const std::optional<double>& v) {
        return v ? given(c, *v * f1_ratio)
                 : missing(c, "no crossing up to " + significant(kRangeTop, 2) + " x pi Dp f1");
    };
    out.push_back(crit(Criterion::order1_backward, critical.order1_backward));
    out.push_back(crit(Criterion::order1_forward, critical.order1_forward));
    out.push_back(crit(Criterion::order2, critical.order2));
    // The order-2 resonance limits only where something loads order 2.
    out.back().limits = std::find(response.orders.begin(), response.orders.end(), 2) != response.orders.end();
    if (!out.back().limits) out.back().note = "no order-2 load (ovality with gravity): reported, not limiting";
    const AmplitudeSafeSpeed& safe = response.safe;
    if (safe.reached)
        out.push_back(given(Criterion::amplitude, safe.web_speed_m_s));
    else
        out.push_back(missing(Criterion::amplitude,
                              "the limit " + significant(response.limit_m * 1e3, 3) + " mm is not reached up to " +
                                  formatted("%.2f", response.points.back().web_speed_m_s) + " m/s"));
    return out;
}

int lowest_limiting(const std::vector<CriterionSpeed>& criteria) {
    int best = -1;
    for (size_t i = 0; i < criteria.size(); ++i)
        if (criteria[i].given && criteria[i].limits &&
            (best < 0 || criteria[i].web_speed_m_s < criteria[best].web_speed_m_s))
            best = static_cast<int>(i);
    return best;
}

ResponseSetup setup_for_range(const ResponseSetup& base, const Scene& at, double f1_estimate_hz) {
    ResponseSetup s = base;
    (void)at;
    s.response.from_web_speed = true;
    s.response.speeds_hz.resize(kResponsePoints);
    for (int i = 0; i < kResponsePoints; ++i)
        s.response.speeds_hz[i] =
            f1_estimate_hz * (kRangeBottom + (kRangeTop - kRangeBottom) * i / (kResponsePoints - 1));
    return s;
}

std::vector<UncertainInput> uncertain_inputs(const Scene& scene, const ResponseSetup& base) {
    std::vector<UncertainInput> out;
    UncertainInput damping = input("damping ratio", "0.005-0.02",
                                   "cores and rest rolls, measured (Ilomaki, On the durability "
                                   "of cores and rest roll dynamics, I-1...I-4; docs/how-to/response.md)",
                                   kDampingLow, kDampingHigh, "zeta");
    if (base.damping.rayleigh)
        damping.applies = false, damping.why_not = "Rayleigh damping: vary alpha and beta in the case";
    out.push_back(damping);
    const double tolerance = kBowPerLength * scene.core.length;
    const double bow = base.excitation.bow_m;
    UncertainInput b = input("bow", "",
                             "Ilomaki: \"the out of straightness of cores should generally be "
                             "no more than "
                             "+-0.5 mm/m\" (upper end); the lower end a core half as bowed",
                             kBowLowFactor * bow, std::max(bow, tolerance), "m at mid-core");
    b.range = significant(b.low * 1e3, 3) + "-" + significant(b.high * 1e3, 3) + " mm";
    if (!(bow > 0)) b.applies = false, b.why_not = "no bow in [excitation]";
    out.push_back(b);
    UncertainInput contact = input("chuck contact stiffness", "x1/3 - x3",
                                   "uncertain by 3-5x (docs/theory/chucks.md, "
                                   "docs/reference/material-sources.md)",
                                   1 / kContactFactor, kContactFactor, "factor on k_n and k_t");
    if (!spring_chucks(scene)) contact.applies = false, contact.why_not = "no spring layer (clamps or bonded chucks)";
    out.push_back(contact);
    out.push_back(input("core E_z", "+-15 %",
                        "assumed: no general spread published "
                        "(docs/reference/material-sources.md); the ISO "
                        "11093-8 value of the core in question narrows it",
                        1 - kCoreModulusSpread, 1 + kCoreModulusSpread, "factor on E_z"));
    UncertainInput g = input("core G_rz", "50-650 MPa", "suggested range (docs/reference/material-sources.md)", 0, 0, "Pa");
    g.applies = false;
    g.why_not = !level_traits(chosen_level(scene)).through_wall_shear ? "the beam level has no through-wall "
                                        "shear; the harmonic level carries it"
                                      : "its effect on f1 is below 1 % per 10 % "
                                        "(docs/reference/material-sources.md); not sampled";
    out.push_back(g);
    UncertainInput stand =
        input("stand stiffness", "x0.5 - x2", "assumed: Ilomaki names the frame's compliance, no number",
              1 / kStandFactor, kStandFactor, "factor on the bearings' and frame's stiffness");
    if (!elastic_stand(scene)) stand.applies = false, stand.why_not = "rigid bearings";
    out.push_back(stand);
    UncertainInput web = input("web tension", "100-1000 N/m",
                               "running web tensions (Roisum, The Mechanics of Web Handling, "
                               "TAPPI 1998)",
                               kWebTensionLow, kWebTensionHigh, "N/m");
    if (!scene.web) web.applies = false, web.why_not = "no [web]";
    out.push_back(web);
    return out;
}

namespace {

// The input a fitted key narrows, or "".
std::string input_of_key(const std::string& key) {
    const bool chuck = key.rfind("supports.", 0) == 0 && (key.find(".normal_stiffness") != std::string::npos ||
                                                          key.find(".expansion_pressure") != std::string::npos);
    if (chuck) return "chuck contact stiffness";
    if (key == "core.material.E_z") return "core E_z";
    return "";
}

}  // namespace

std::vector<std::string> narrow_by_fit(std::vector<UncertainInput>& inputs, const FitOutcome& fit,
                                       const std::string& measurements_file) {
    std::vector<std::string> out;
    for (const FitParameter& p : fit.parameters) {
        const std::string name = input_of_key(p.key);
        if (name.empty() || !p.uncertainty || !(p.value > 0)) continue;
        for (UncertainInput& i : inputs) {
            if (i.name != name || !i.applies) continue;
            // ln p is what the fit estimates: its standard uncertainty is u / p.
            const double spread = std::exp(kFitSigmas * *p.uncertainty / p.value);
            if (1 / spread <= i.low && spread >= i.high) continue;  // no narrower than the documented range
            i.low = std::max(i.low, 1 / spread), i.high = std::min(i.high, spread);
            i.range = "x" + significant(i.low, 3) + " - x" + significant(i.high, 3);
            i.source = "fitted: " + p.key + " = " + significant(p.value, 4) + " (SI), standard uncertainty " +
                       significant(*p.uncertainty, 2) + ", from the measured frequencies of " + measurements_file +
                       " (coremodal fit); the range is +-" + significant(kFitSigmas, 1) + " of them";
            out.push_back(name + " " + i.range + " (" + p.key + " fitted)");
        }
    }
    return out;
}

void propagate_band(const Scene& scene, const ResponseSetup& base, const std::vector<UncertainInput>& inputs,
                    LimitsPoint& point, int& n_solves) {
    const Scene at = scene_at_diameter(scene, point.diameter_m);
    CriticalSpeeds critical;
    const auto value = [&](Criterion c) -> std::optional<double> {
        const CriterionSpeed& s = point.at(c);
        return s.given ? std::optional<double>(s.web_speed_m_s) : std::nullopt;
    };
    critical.order1_backward = value(Criterion::order1_backward);
    critical.order1_forward = value(Criterion::order1_forward);
    critical.order2 = value(Criterion::order2);
    const int own = lowest_limiting(point.criteria);
    point.safe_low_m_s = point.safe_high_m_s = own >= 0 ? point.criteria[own].web_speed_m_s : 0;
    const double f1_estimate = point.f1_hz;
    const auto absorb = [&](const ResponseResult& r) {
        ++n_solves;
        const double ratio = point.f1_hz > 0 ? r.speeds_at_rest.f1_hz / point.f1_hz : 1.0;
        std::vector<CriterionSpeed> sample = criteria_of(r, critical, ratio);
        // The criteria the roll's inputs do not move (traction) as they are.
        for (size_t i = sample.size(); i < point.criteria.size(); ++i) sample.push_back(point.criteria[i]);
        for (size_t i = 0; i < sample.size(); ++i) {
            if (!sample[i].given) continue;
            CriterionSpeed& c = point.criteria[i];
            const double x = sample[i].web_speed_m_s;
            if (!c.given && c.band_low_m_s == 0 && c.band_high_m_s == 0) c.band_low_m_s = c.band_high_m_s = x;
            c.band_low_m_s = std::min(c.band_low_m_s, x), c.band_high_m_s = std::max(c.band_high_m_s, x);
        }
        const int lowest = lowest_limiting(sample);
        if (lowest < 0) return;
        point.safe_low_m_s = std::min(point.safe_low_m_s, sample[lowest].web_speed_m_s);
        point.safe_high_m_s = std::max(point.safe_high_m_s, sample[lowest].web_speed_m_s);
    };
    // The samples that change neither K nor M (damping, bow) on one model of
    // the scene at this diameter (run_forced_responses); the others each on
    // their own scene. Every sample is checked once per verdict (at the point).
    std::vector<ResponseSetup> same_scene;
    for (const UncertainInput& input : inputs) {
        if (!input.applies) continue;
        const Apply apply = apply_of(input.name);
        for (double v : {input.low, input.high}) {
            Scene s = at;
            ResponseSetup setup = setup_for_range(base, at, f1_estimate);
            apply(s, setup, v);
            if (changes_setup_only(input.name))
                same_scene.push_back(std::move(setup));
            else
                absorb(run_forced_response(s, setup, {}, ResponseChecking::none, RestModes::lateral));
        }
    }
    if (!same_scene.empty())
        for (const ResponseResult& r : run_forced_responses(at, same_scene, ResponseChecking::none, RestModes::lateral))
            absorb(r);
}

std::vector<std::string> limits_assumptions(const Scene& scene, bool case_response, const ResponseSetup& base) {
    std::vector<std::string> out;
    if (case_response) {
        out.push_back(
            "damping and excitation from the case's [damping] and "
            "[excitation]; the speeds are the "
            "verdict's own (" +
            std::to_string(kResponsePoints) + " from " + significant(kRangeBottom, 2) + " to " +
            significant(kRangeTop, 2) + " x pi Dp f1 at every diameter)");
        return out;
    }
    out.push_back(
        "damping ratio 0.01 on every mode: the middle of the measured "
        "0.005-0.02 of cores and rest rolls "
        "(Ilomaki, I-1...I-4; docs/how-to/response.md)");
    out.push_back("bow " + significant(base.excitation.bow_m * 1e3, 3) +
                  " mm at mid-core, a half sine: Ilomaki's "
                  "straightness tolerance +-0.5 mm per metre of core (" +
                  significant(scene.core.length, 4) + " m)");
    out.push_back(
        "gravity acts; no unbalance, eccentricity or ovality (give "
        "[excitation] for them)");
    out.push_back("amplitude limit " + significant(base.response.limit_m * 1e3, 3) +
                  " mm at mid-span: Ilomaki's +-5 mm, which I-5's factor 0.7-0.8 "
                  "is meant to keep");
    return out;
}

}  // namespace coremodal
