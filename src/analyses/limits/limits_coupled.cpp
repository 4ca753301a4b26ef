// The verdict for a scene at the coupled level (segmented chucks): f1, the
// chuck factor and the criteria from f1 at the coupled level, every spinning
// criterion at the harmonic level of the axisymmetric equivalent
// (limits.hpp, coupled_verdict; docs/how-to/limits.md, "Segmented chucks").
#include "analyses/limits/limits.hpp"

#include "analyses/limits/limits_band.hpp"
#include "analyses/run/run.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/join.hpp"
#include "common/stopwatch.hpp"
#include "models/choose.hpp"
#include "models/coupled/axisymmetric_equivalent.hpp"
#include "models/model_level.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// The coupled level's run of the scene at one diameter: what `coremodal run
// --model coupled` gives for it (f1, the chuck factor by the free span's
// run). `level` is kept over the unwind: each diameter's search for N starts
// one step below the last diameter's N (models/coupled/coupled_level.hpp).
RunReport coupled_run(const Scene& at, ModelLevel& level) {
    RunOptions options;
    options.quiet = true;
    options.write_results = false;
    options.chuck_factor_by_fe = true;
    return run_scene(at, options, level);
}

// Criterion c from the coupled level's f1: its value v (or why none), its
// band the equivalent's relative to its own point value (the same ranges
// move f1 by similar fractions at both levels).
void set_from_coupled(CriterionSpeed& s, const std::optional<double>& v, const std::string& why) {
    const double old = s.web_speed_m_s;
    const double low = s.given && old > 0 ? s.band_low_m_s / old : 1.0;
    const double high = s.given && old > 0 ? s.band_high_m_s / old : 1.0;
    s.level = "coupled";
    if (!v) {
        s.given = false, s.note = why, s.band_low_m_s = s.band_high_m_s = 0;
        return;
    }
    s.given = true;
    s.web_speed_m_s = *v;
    s.band_low_m_s = std::min(*v, *v * low), s.band_high_m_s = std::max(*v, *v * high);
}

// One point of the equivalent's verdict made the coupled scene's: f1, k,
// I-5 and Koenig at the coupled level, then the governing criterion and the
// safe speed's band again. The band of the safe speed is the envelope of the
// limiting criteria's bands (the lowest of their low ends, the lowest of
// their high ends): it contains every sample's own verdict.
void at_coupled_level(const Scene& scene, ModelLevel& level, const std::string& spinning_level, LimitsPoint& p,
                      int& n_solves) {
    const RunReport run = coupled_run(scene_at_diameter(scene, p.diameter_m), level);
    ++n_solves;
    const double f1 = run.beam.fe_first_bending_hz;
    if (!(f1 > 0))
        throw SolveError(scene.source_file + ": no first bending mode at the coupled level at rest-roll diameter " +
                         significant(p.diameter_m * 1e3, 5) + " mm; expected [analysis] modes to include it");
    p.equivalent_f1_hz = p.f1_hz;
    p.f1_hz = f1;
    p.chuck_factor.reset();
    if (run.chuck) {
        p.chuck_factor = run.chuck->chuck_factor > 0 ? run.chuck->chuck_factor : run.chuck->chuck_factor_beam;
        p.f2_hz = run.chuck->f2_fe_hz > 0 ? run.chuck->f2_fe_hz : run.chuck->f2_beam_hz;
    }
    const RollSpeeds speeds = report_speeds(run);
    for (size_t i = 0; i < 2; ++i) {
        CriterionSpeed& s = p.criteria[static_cast<int>(i == 0 ? Criterion::i5_low : Criterion::i5_high)];
        set_from_coupled(
            s,
            speeds.given() && speeds.safe.size() > i ? std::optional<double>(speeds.safe[i].v_safe_m_s) : std::nullopt,
            speeds.not_given);
    }
    set_from_coupled(p.criteria[static_cast<int>(Criterion::koenig)],
                     speeds.koenig ? std::optional<double>(
                                         speeds.koenig->v_krit_large_core_m_s.value_or(speeds.koenig->speed.v_krit_m_s))
                                   : std::nullopt,
                     "no free span between two supports");
    for (Criterion c : {Criterion::order1_backward, Criterion::order1_forward, Criterion::order2, Criterion::amplitude})
        p.criteria[static_cast<int>(c)].level = spinning_level;
    p.governing = lowest_limiting(p.criteria);
    if (p.governing < 0)
        throw SolveError("no criterion gives a web speed at rest-roll diameter " + significant(p.diameter_m * 1e3, 5) +
                         " mm; expected at least I-5 from the first bending mode");
    p.safe_m_s = p.criteria[p.governing].web_speed_m_s;
    p.safe_low_m_s = p.safe_m_s;
    p.safe_high_m_s = -1;
    for (const CriterionSpeed& c : p.criteria)
        if (c.given && c.limits) {
            p.safe_low_m_s = std::min(p.safe_low_m_s, c.band_low_m_s);
            p.safe_high_m_s = p.safe_high_m_s < 0 ? c.band_high_m_s : std::min(p.safe_high_m_s, c.band_high_m_s);
        }
    p.safe_high_m_s = std::max(p.safe_high_m_s, p.safe_m_s);
}

// The progress line of one diameter at the coupled level (k of n).
std::string coupled_point_line(const LimitsPoint& p, long k, size_t n, double seconds) {
    return "  D = " + formatted("%.1f", p.diameter_m * 1e3) + " mm (" + std::to_string(k) + "/" + std::to_string(n) +
           "): f1 " + significant(p.f1_hz, 5) + " Hz at the coupled level" +
           (p.chuck_factor ? ", k " + formatted("%.3f", *p.chuck_factor) : "") + ", safe " +
           formatted("%.2f", p.safe_m_s) + " m/s, " + formatted("%.1f", seconds) + " s";
}

// The coupled level's f1 against the equivalent's at every diameter, in
// words; a warning where the difference exceeds the width of I-5's band.
void compare_f1(LimitsResult& r) {
    std::vector<std::string> all, beyond;
    for (const LimitsPoint& p : r.points) {
        if (!p.equivalent_f1_hz) continue;
        const double diff = (*p.equivalent_f1_hz - p.f1_hz) / p.f1_hz;
        const CriterionSpeed& i5 = p.at(Criterion::i5_low);
        const double width = i5.given ? (i5.band_high_m_s - i5.band_low_m_s) / i5.web_speed_m_s : 0.0;
        const std::string at = significant(p.diameter_m * 1e3, 4) + " mm " + formatted("%+.2f", 100 * diff) + " %";
        all.push_back(at);
        if (std::abs(diff) > width) beyond.push_back(at + " (I-5's band " + formatted("%.2f", 100 * width) + " %)");
    }
    r.notes.push_back("f1 of the axisymmetric equivalent against the coupled level's, at " + join(all, ", "));
    if (!beyond.empty())
        r.warnings.push_back(
            "the axisymmetric equivalent's f1 differs from the coupled level's by more than the band's width at " +
            join(beyond, ", ") +
            ": the critical speeds and the forced response, from the equivalent, are off by about as much "
            "(the pads' coupling of n = 1 to n = |1 +- j N| it leaves out); model = \"solid\" carries them "
            "with the pads themselves");
}

}  // namespace

LimitsResult coupled_verdict(const Scene& case_scene, const std::optional<ResponseSetup>& response,
                             const LimitsRequest& request) {
    Stopwatch clock;
    Scene scene = case_scene;
    scene.model = ModelChoice::coupled;
    const AxisymmetricEquivalent equivalent = axisymmetric_equivalent(scene);
    Scene harmonic = equivalent.scene;
    harmonic.model = ModelChoice::harmonic;
    request.say("limits: segmented chucks: the spinning criteria and the band at the harmonic level of the "
                "axisymmetric equivalent (the pads as full bands of their coverage)");
    LimitsResult r = verdict(harmonic, response, request);
    r.level = ModelChoice::coupled;
    const std::string spinning =
        "harmonic, axisymmetric equivalent (pads' coverage " + significant(100 * equivalent.coverage, 3) + " %)";
    request.say("limits: f1, k, I-5 and Koenig at the coupled level (the pads themselves) at the same " +
                std::to_string(r.points.size()) + " diameters");
    const std::unique_ptr<ModelLevel> level = make_model_level(scene);
    for (LimitsPoint& p : r.points) {
        Stopwatch lap;
        at_coupled_level(scene, *level, spinning, p, r.n_solves);
        request.say(coupled_point_line(p, &p - r.points.data() + 1, r.points.size(), lap.seconds()));
    }
    conclude(r, request);
    compare_f1(r);
    r.assumptions.insert(r.assumptions.begin(),
                         {"levels: f1, the chuck factor k, I-5 and Koenig at the coupled level (the pads themselves); "
                          "the order-1 and order-2 critical speeds, the forced response and the band at the " +
                              spinning,
                          equivalent.assumption});
    r.seconds = clock.lap();
    return r;
}

}  // namespace coremodal
