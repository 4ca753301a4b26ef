#include "analyses/limits/limits.hpp"

#include "analyses/campbell/campbell.hpp"
#include "analyses/limits/limits_band.hpp"
#include "analyses/run/run.hpp"
#include "beam/beam_model.hpp"
#include "beam/rotating_modes.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/join.hpp"
#include "common/stopwatch.hpp"
#include "effects/rotation.hpp"
#include "models/choose.hpp"
#include "models/coupled/axisymmetric_equivalent.hpp"
#include "modes/tracking.hpp"
#include "scene/limits_spec.hpp"
#include "scene/rotation_spec.hpp"
#include "scene/traction_case.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

std::vector<double> spaced(double first, double last, int n) {
    std::vector<double> out(n);
    for (int i = 0; i < n; ++i) out[i] = first + (last - first) * i / (n - 1);
    return out;
}

// Whether some chuck presses on the bore with segmented pads (the coupled
// level's verdict: coupled_verdict).
bool has_pads(const Scene& scene) {
    for (const ChuckSpec& chuck : scene.supports.chucks)
        for (const ExpandingElement& e : chuck.expanding)
            if (e.segments > 0) return true;
    return false;
}

// Whether the scene's level cannot spin (the coupled harmonics: level_traits)
// while its pads break the symmetry: the spinning criteria then come from
// the axisymmetric equivalent, the rest at the level itself (coupled_verdict).
bool spins_by_equivalent(const Scene& scene) {
    return !level_traits(chosen_level(scene)).spins && has_pads(scene);
}

// The scene at the beam level (Eigen only, milliseconds): its f1 sets the
// speed range of the level's own solves.
BeamModelResult beam_level(const Scene& scene) {
    Scene beam = scene;
    beam.model = ModelChoice::beam;
    return solve_beam_model(beam);
}

double first_bending_hz(const Scene& scene, const BeamModelResult& beam) {
    for (const BeamMode& m : beam.modes)
        if (m.label.type == "bending") return m.frequency_hz;
    throw SolveError(scene.name + ": no bending mode among the lowest " + std::to_string(scene.analysis.n_modes) +
                     " modes at rest; expected [analysis] modes to include the "
                     "first bending mode");
}

// Step 2 at the beam level with both bending planes alike: the same
// crossings, exactly, from the plane problem's pencils
// (beam/rotating_modes.hpp, plane_critical_speeds; tests/unit/analyses/limits
// hold them against the Campbell sweep), in a few milliseconds instead of a
// sweep with refined crossings; none where the planes differ.
std::optional<CriticalSpeeds> pencil_speeds(const BeamModelResult& beam, double dp, double f1_estimate_hz,
                                            std::string& mode) {
    const std::optional<std::vector<PlaneCrossing>> crossings =
        plane_critical_speeds(beam.network, beam.lambda_scale, {1, 2}, kRangeTop * f1_estimate_hz);
    if (!crossings) return std::nullopt;
    CriticalSpeeds out;
    for (const PlaneCrossing& c : *crossings) {  // ascending speed
        std::optional<double>& slot = c.order == 2                ? out.order2
                                      : c.whirl == Whirl::forward ? out.order1_forward
                                                                  : out.order1_backward;
        if (slot) continue;
        slot = web_speed(c.speed_hz, dp);
        if (c.order == 1 && mode.empty()) mode = label_text(c.label);
    }
    return out;
}

// Step 2 at the harmonic level: the crossings of the forced response's own
// n = 1 model in its kept modes (ResponseResult::crossings), exact for that
// model, instead of a Campbell sweep over every wave number (the criteria
// need the n = 1 family only: every load of the verdict is lateral). They
// agree with the sweep's refined crossings within 0.2 % (tests/unit/analyses/
// limits; docs/how-to/limits.md, "Speed").
CriticalSpeeds response_crossing_speeds(const ResponseResult& response, std::string& mode) {
    CriticalSpeeds out;
    for (const ResponseCrossing& c : response.crossings) {  // ascending speed
        std::optional<double>& slot = c.order == 2 ? out.order2 : c.forward ? out.order1_forward : out.order1_backward;
        if (slot) continue;
        slot = c.web_speed_m_s;
        if (c.order == 1 && mode.empty()) mode = label_text(c.mode);
    }
    return out;
}

// Step 2: the critical web speeds of the spinning roll, by the level's
// Campbell machinery over 0 .. kRangeTop x the first critical speed.
CriticalSpeeds campbell_speeds(const Scene& scene, double f1_estimate_hz, std::string& mode) {
    RotationSpec rotation;
    rotation.speeds_hz = spaced(0, kRangeTop * f1_estimate_hz, kCampbellPoints);
    rotation.from_web_speed = true;
    rotation.excitation_orders = {1, 2};
    const CampbellResult campbell = run_campbell(scene, rotation);
    CriticalSpeeds out;
    for (const WhirlCrossing& c : campbell.critical) {  // ascending speed
        std::optional<double>* slot = nullptr;
        if (c.order == 2 && !out.order2) slot = &out.order2;
        if (c.order == 1 && c.whirl == Whirl::backward && !out.order1_backward) slot = &out.order1_backward;
        if (c.order == 1 && c.whirl == Whirl::forward && !out.order1_forward) slot = &out.order1_forward;
        if (c.order == 1 && c.whirl == Whirl::none)  // planar: the one crossing is both
            slot = !out.order1_backward ? &out.order1_backward : !out.order1_forward ? &out.order1_forward : nullptr;
        if (!slot) continue;
        *slot = c.web_speed_m_s;
        if (c.order == 1 && mode.empty()) mode = label_text(c.label);
    }
    return out;
}

// Step 2 at one diameter: the point values.
// The forced response checks its superposition once per verdict, at the
// first diameter solved (the case's roll); every other diameter and band
// sample is the same computation on a changed scene.
LimitsPoint solve_point(const Scene& scene, const ResponseSetup& base, double d, LimitsResult& result) {
    LimitsPoint p;
    p.diameter_m = d;
    const Scene at = scene_at_diameter(scene, d);
    const BeamModelResult beam = beam_level(at);
    const double f1_estimate = first_bending_hz(at, beam);
    const ResponseSetup setup = setup_for_range(base, at, f1_estimate);
    const bool check = result.check_response && !result.checks;
    const ResponseResult response =
        run_forced_response(at, setup, {}, check ? ResponseChecking::light : ResponseChecking::none, RestModes::lateral);
    if (check) result.checks = LimitsChecks{d, response.checks};
    std::optional<CriticalSpeeds> critical;
    if (level_traits(at.model).pencil_critical_speeds)
        critical = pencil_speeds(beam, roll_outer_diameter(at), f1_estimate, p.order1_mode);
    else if (!response.crossings.empty())  // the harmonic level's n = 1 crossings, from the response's own modes
        critical = response_crossing_speeds(response, p.order1_mode);
    if (!critical && !result.campbell_sweep)
        throw InputError("the roll's bending planes differ (a web or unlike supports), so its critical speeds need "
                         "the Campbell sweep");
    if (!critical) critical = campbell_speeds(at, f1_estimate, p.order1_mode);
    result.n_solves += 2;
    p.f1_hz = response.speeds_at_rest.f1_hz;
    if (at.supports.kind == SupportKind::chucks && p.f1_hz > 0) {
        const ChuckFactor k = chuck_factor(at, p.f1_hz, true);
        p.chuck_factor = k.chuck_factor > 0 ? k.chuck_factor : k.chuck_factor_beam;
        p.f2_hz = k.f2_fe_hz > 0 ? k.f2_fe_hz : k.f2_beam_hz;
    }
    p.criteria = criteria_of(response, *critical, 1.0);
    p.peaks = response.peaks;
    for (const ResponsePoint& r : response.points) p.amplitude.emplace_back(r.web_speed_m_s, r.probes.at(0).total_m);
    return p;
}

std::string diameter_mm(double d_m) { return formatted("%.1f", d_m * kMmPerM); }

// The progress line of one diameter solved (k of n; beyond n: a midpoint).
std::string point_line(const LimitsPoint& p, size_t k, size_t n, double seconds) {
    const std::string which = k <= n ? std::to_string(k) + "/" + std::to_string(n) : "midpoint";
    std::string line =
        "  D = " + diameter_mm(p.diameter_m) + " mm (" + which + "): f1 " + significant(p.f1_hz, 5) + " Hz";
    if (p.governing >= 0)
        line += ", safe " + formatted("%.2f", p.safe_m_s) + " m/s (" +
                criterion_name(p.criteria[p.governing].criterion) + ")";
    return line + (p.band_sampled ? ", band sampled" : "") + ", " + formatted("%.1f", seconds) + " s";
}

// The traction line of a case without [traction].
CriterionSpeed no_roller() {
    CriterionSpeed s;
    s.criterion = Criterion::traction;
    s.note = "no [traction] roller in the case";
    return s;
}

// Step 4 at one point: the lowest limiting criterion given, and the safe
// speed's band from the samples' own verdicts.
void govern(LimitsPoint& p) {
    p.governing = lowest_limiting(p.criteria);
    if (p.governing < 0)
        throw SolveError("no criterion gives a web speed at rest-roll diameter " + significant(p.diameter_m * 1e3, 5) +
                         " mm; expected at least I-5 from the first bending mode");
    p.safe_m_s = p.criteria[p.governing].web_speed_m_s;
}

// Between two points whose bands were sampled: the band of `p` relative to
// its point values, interpolated linearly in the diameter.
double relative_at(double d, double da, double ra, double db, double rb) {
    return da == db ? ra : ra + (rb - ra) * (d - da) / (db - da);
}

void interpolate_bands(std::vector<LimitsPoint>& points) {  // largest diameter first
    for (size_t i = 0; i < points.size(); ++i) {
        LimitsPoint& p = points[i];
        if (p.band_sampled) continue;
        const LimitsPoint* a = nullptr;
        const LimitsPoint* b = nullptr;
        for (size_t j = i; j-- > 0;)
            if (points[j].band_sampled) {
                a = &points[j];
                break;
            }
        for (size_t j = i + 1; j < points.size(); ++j)
            if (points[j].band_sampled) {
                b = &points[j];
                break;
            }
        if (!a) a = b;
        if (!b) b = a;
        if (!a) return;
        const auto ratio = [](double band, double value) { return value > 0 ? band / value : 1.0; };
        for (size_t k = 0; k < p.criteria.size(); ++k) {
            CriterionSpeed& c = p.criteria[k];
            if (!c.given) continue;
            const CriterionSpeed &ca = a->criteria[k], &cb = b->criteria[k];
            const double la = ca.given ? ratio(ca.band_low_m_s, ca.web_speed_m_s) : 1.0;
            const double lb = cb.given ? ratio(cb.band_low_m_s, cb.web_speed_m_s) : 1.0;
            const double ha = ca.given ? ratio(ca.band_high_m_s, ca.web_speed_m_s) : 1.0;
            const double hb = cb.given ? ratio(cb.band_high_m_s, cb.web_speed_m_s) : 1.0;
            c.band_low_m_s = c.web_speed_m_s * relative_at(p.diameter_m, a->diameter_m, la, b->diameter_m, lb);
            c.band_high_m_s = c.web_speed_m_s * relative_at(p.diameter_m, a->diameter_m, ha, b->diameter_m, hb);
        }
        const double low = relative_at(p.diameter_m, a->diameter_m, ratio(a->safe_low_m_s, a->safe_m_s), b->diameter_m,
                                       ratio(b->safe_low_m_s, b->safe_m_s));
        const double high = relative_at(p.diameter_m, a->diameter_m, ratio(a->safe_high_m_s, a->safe_m_s),
                                        b->diameter_m, ratio(b->safe_high_m_s, b->safe_m_s));
        p.safe_low_m_s = std::min(p.safe_m_s, p.safe_m_s * low);
        p.safe_high_m_s = std::max(p.safe_m_s, p.safe_m_s * high);
    }
}

// Step 1: one pass of midpoints where the verdict changes fast.
std::vector<double> midpoints(const std::vector<LimitsPoint>& points) {
    std::vector<double> out;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const LimitsPoint &a = points[i], &b = points[i + 1];
        const bool switched = a.governing != b.governing;
        const bool fast = std::abs(a.safe_m_s - b.safe_m_s) > kFastChange * std::min(a.safe_m_s, b.safe_m_s);
        if (switched || fast) out.push_back(0.5 * (a.diameter_m + b.diameter_m));
    }
    return out;
}

// Step 4: where the conservative safe speed falls below the target, scanning
// the unwind from the largest diameter down (linear between diameters).
RollChange roll_change(const std::vector<LimitsPoint>& points, double target) {
    RollChange c;
    c.target_m_s = target;
    c.margin_m_s = points.front().safe_low_m_s - target;
    c.diameter_m = points.back().diameter_m;
    if (points.front().safe_low_m_s < target) {
        c.never_safe = c.needed = true;
        c.diameter_m = points.front().diameter_m;
        return c;
    }
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const LimitsPoint &a = points[i], &b = points[i + 1];
        if (b.safe_low_m_s >= target) continue;
        const double t = (a.safe_low_m_s - target) / (a.safe_low_m_s - b.safe_low_m_s);
        c.needed = true;
        c.diameter_m = a.diameter_m + t * (b.diameter_m - a.diameter_m);
        return c;
    }
    return c;
}

Verdict the_verdict(const LimitsResult& r) {
    Verdict v;
    // A target out of reach already at the full roll changes nothing: the
    // verdict is then the whole unwind's, and the line says the target's margin.
    const bool changes = r.change && r.change->needed && !r.change->never_safe;
    const double change = changes ? r.change->diameter_m : r.points.back().diameter_m;
    v.diameter_m = change;
    const LimitsPoint* lowest = nullptr;
    for (const LimitsPoint& p : r.points)
        if (p.diameter_m >= change - 1e-12 && (!lowest || p.safe_low_m_s < lowest->safe_low_m_s)) lowest = &p;
    if (!lowest) lowest = &r.points.front();  // never safe: the full roll
    v.speed_m_s = lowest->safe_low_m_s;
    v.band_low_m_s = lowest->safe_low_m_s, v.band_high_m_s = lowest->safe_high_m_s;
    v.governed_by = criterion_name(static_cast<Criterion>(lowest->governing));
    v.at_diameter_m = lowest->diameter_m;
    return v;
}

}  // namespace

CriterionSpeed traction_slip_criterion(const TractionSpec& spec) {
    CriterionSpeed s;
    s.criterion = Criterion::traction;
    s.given = true;
    s.web_speed_m_s = spec.tension_difference ? slip_speed(spec, *spec.tension_difference) : zero_traction_speed(spec);
    s.band_low_m_s = s.band_high_m_s = s.web_speed_m_s;
    s.note = spec.tension_difference ? "the roller can no longer carry [traction] tension_difference "
                                       "(Rice & Gans, eqs. 12-13)"
                                     : "traction vanishes (Rice & Gans, P* = 1); give [traction] "
                                       "tension_difference for the slip speed";
    return s;
}

const char* criterion_id(Criterion c) {
    static const char* ids[] = {"i5_0.7",         "i5_0.8", "koenig",          "order1_backward",
                                "order1_forward", "order2", "amplitude_limit", "traction_slip"};
    return ids[static_cast<int>(c)];
}

const char* criterion_name(Criterion c) {
    static const char* names[] = {
        "I-5 x0.7",         "I-5 x0.8",        "Koenig K-1/K-2",     "order-1 critical BW", "order-1 critical FW",
        "order-2 critical", "amplitude limit", "web slip (traction)"};
    return names[static_cast<int>(c)];
}

Scene scene_at_diameter(const Scene& scene, double d) {
    Scene out = scene;
    const double core = scene.core.outer_diameter;
    // Below a micrometre of paper the roll is the bare core.
    constexpr double kBare = 1e-6;
    if (d <= core + kBare) {
        out.rest_paper.reset();
        return out;
    }
    RestPaperSpec paper = scene.rest_paper.value_or(RestPaperSpec{});
    COREMODAL_ASSERT(scene.rest_paper.has_value());  // the reader keeps the diameters within
                                                     // the case's roll
    paper.outer_diameter = d;
    out.rest_paper = paper;
    return out;
}

ResponseSetup default_limits_setup(const Scene& scene, double limit_m) {
    ResponseSetup s;
    s.damping.ratio = kDefaultDampingRatio;
    s.damping.source =
        "ratio = 0.01 (the verdict's default: the middle of the "
        "measured 0.005-0.02)";
    s.excitation.bow_m = kBowPerLength * scene.core.length;
    s.excitation.gravity = true;
    s.response.limit_m = limit_m;
    s.response.from_web_speed = true;
    s.response.probes = {{std::string(kMidSpan), 0.5 * scene.core.length}};
    return s;
}

void require_limits_scene(const Scene& scene, const LimitsRequest& request) {
    if (scene.supports.kind == SupportKind::free)
        throw InputError(scene.source_file +
                         ": [supports] is free-free; `coremodal limits` needs a roll held in "
                         "its "
                         "stand: expected [supports] type = \"clamped\" or \"chucks\"");
    const ModelChoice level = chosen_level(scene);
    if (spins_by_equivalent(scene)) {
        Scene equivalent = axisymmetric_equivalent(scene).scene;
        equivalent.model = ModelChoice::harmonic;
        require_limits_scene(equivalent, request);
        return;
    }
    if (!level_traits(level).spins)
        throw InputError(scene.source_file + ": model = \"" + to_string(level) +
                         "\" cannot carry the verdict's critical speeds and forced response (" +
                         level_traits(level).why_not_spinning + "); "
                         "expected model = \"beam\" or \"harmonic\" (a body of revolution), or "
                         "\"solid\", or \"coupled\" with segmented chucks (docs/how-to/limits.md)");
    Scene resolved = scene;
    resolved.model = level;
    require_spinning_level(resolved);
    require_response_level(resolved);
    const std::optional<double> target =
        request.target_web_speed_m_s ? request.target_web_speed_m_s : request.spec.target_web_speed_m_s;
    if (target && !(*target > 0))
        throw InputError("--speed = " + significant(*target) + " m/s: the target web speed must be above 0 m/s");
}

LimitsResult verdict(const Scene& case_scene, const std::optional<ResponseSetup>& response,
                     const LimitsRequest& request) {
    require_limits_scene(case_scene, request);
    if (spins_by_equivalent(case_scene)) return coupled_verdict(case_scene, response, request);
    Stopwatch clock;
    Scene scene = case_scene;
    scene.model = chosen_level(case_scene);
    LimitsResult r;
    r.level = scene.model;
    r.band = request.spec.band;
    r.check_response = request.check_response;
    r.campbell_sweep = request.campbell_sweep;
    r.limit_m = request.spec.limit_m.value_or(response ? response->response.limit_m : kDefaultAmplitudeLimit);
    ResponseSetup base = response.value_or(default_limits_setup(scene, r.limit_m));
    base.response.limit_m = r.limit_m;
    r.damping_summary = damping_summary(base.damping);
    r.bow_m = base.excitation.bow_m;
    r.assumptions = limits_assumptions(scene, response.has_value(), base);
    r.inputs = request.inputs.value_or(uncertain_inputs(scene, base));
    if (request.fit) {
        const std::vector<std::string> narrowed = narrow_by_fit(r.inputs, *request.fit, request.fit_file);
        r.assumptions.push_back("the case's keys fitted to the measured frequencies of " + request.fit_file +
                                " (coremodal fit): " +
                                (narrowed.empty() ? std::string("no range of the band is narrower for it")
                                                  : "the band's ranges narrowed: " + join(narrowed, "; ")));
    }
    // 1. The diameters.
    const double largest = request.spec.largest_diameter_m.value_or(roll_outer_diameter(scene));
    const double smallest = request.spec.smallest_diameter_m.value_or(scene.core.outer_diameter);
    const int n = largest > smallest ? request.spec.points : 1;
    const std::vector<double> diameters = n > 1 ? spaced(largest, smallest, n) : std::vector<double>{largest};
    request.say("limits: " + std::to_string(n) + " rest-roll diameters from " + diameter_mm(largest) + " to " +
                diameter_mm(smallest) + " mm at the " + to_string(scene.model) + " level" +
                (r.band ? ", the band at every " + std::to_string(kBandStride) + "th" : ""));
    auto solve = [&](double d, bool added, bool sample_band) {
        Stopwatch lap;
        LimitsPoint p = solve_point(scene, base, d, r);
        p.criteria.push_back(request.traction.value_or(no_roller()));
        p.added = added;
        p.band_sampled = r.band && sample_band;
        if (p.band_sampled) propagate_band(scene, base, r.inputs, p, r.n_solves);
        govern(p);
        if (!p.band_sampled) p.safe_low_m_s = p.safe_high_m_s = p.safe_m_s;
        request.say(point_line(p, r.points.size() + 1, diameters.size(), lap.seconds()));
        return p;
    };
    for (int i = 0; i < static_cast<int>(diameters.size()); ++i)
        r.points.push_back(solve(diameters[i], false, i % kBandStride == 0 || i + 1 == n));
    for (double d : midpoints(r.points)) r.points.push_back(solve(d, true, false));
    std::sort(r.points.begin(), r.points.end(),
              [](const LimitsPoint& a, const LimitsPoint& b) { return a.diameter_m > b.diameter_m; });
    if (r.band) interpolate_bands(r.points);
    conclude(r, request);
    r.seconds = clock.lap();
    return r;
}

// Steps 4 and 5 on the governed points.
void conclude(LimitsResult& r, const LimitsRequest& request) {
    const std::optional<double> target =
        request.target_web_speed_m_s ? request.target_web_speed_m_s : request.spec.target_web_speed_m_s;
    if (target) r.change = roll_change(r.points, *target);
    r.verdict = the_verdict(r);
    r.warnings.clear();
    warn(r);
    r.notes = limits_notes(r);
}

std::string verdict_line(const LimitsResult& r) {
    const Verdict& v = r.verdict;
    const bool changes = r.change && r.change->needed && !r.change->never_safe;
    std::string line = "safe up to " + formatted("%.2f", v.speed_m_s) + " m/s " +
                       (changes ? "at roll change, D = " : "down to D = ") + formatted("%.1f", v.diameter_m * 1e3) +
                       " mm; governed by " + v.governed_by + " at " + formatted("%.1f", v.at_diameter_m * 1e3) +
                       " mm; band " + formatted("%.2f", v.band_low_m_s) + "-" + formatted("%.2f", v.band_high_m_s) +
                       " m/s";
    if (!r.change) return line;
    line += "; target " + formatted("%.2f", r.change->target_m_s) + " m/s";
    if (r.change->never_safe)
        return line + " is above the safe speed already at the full roll (margin " +
               formatted("%+.2f", r.change->margin_m_s) + " m/s)";
    return line + (changes ? "" : " holds down to the smallest diameter") + ", margin at the full roll " +
           formatted("%+.2f", r.change->margin_m_s) + " m/s";
}

std::string stand_verdict_line(const std::string& case_file) {
    const LimitsCase c = parse_limits_case(case_file);
    if (c.scene.supports.kind == SupportKind::free) return "";
    Scene scene = c.scene;
    scene.model = ModelChoice::beam;
    LimitsRequest request;
    request.spec = c.limits.value_or(LimitsSpec{});
    const double d = roll_outer_diameter(scene);
    request.spec.largest_diameter_m = request.spec.smallest_diameter_m = d;
    request.spec.band = false;
    request.check_response = false;
    request.campbell_sweep = false;
    if (const std::optional<TractionCase> roller = read_traction_case(case_file))
        request.traction = traction_slip_criterion(roller->spec);
    const std::string what =
        "verdict at the case's roll (beam level, no band; "
        "`coremodal limits` for the unwind and "
        "its band): ";
    try {
        return what + verdict_line(verdict(scene, c.response, request));
    } catch (const std::exception& e) {  // InputError, SolveError: the run itself stands
        return what + "not given: " + e.what();
    }
}

}  // namespace coremodal
