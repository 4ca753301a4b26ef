// How fast may this roll run in this stand: one verdict over the whole
// unwind (`coremodal limits`, docs/how-to/limits.md). The rest roll unwinds from the
// case's roll (or [limits] diameters) down to the bare core; at every
// rest-roll diameter every criterion the project computes gives a web speed,
// the lowest that limits governs, and a band from the uncertain inputs'
// documented ranges says how sure it is.
//
// 1. The diameters: [limits] points equally spaced from the largest to the
//    smallest, then one pass of midpoints where the governing criterion
//    changes or the safe speed moves by more than kFastChange.
// 2. At each diameter (the scene with its rest paper at that diameter):
//    the forced response (analyses/response: f1 at rest at the scene's
//    level, I-5 at 0.7 and 0.8, Koenig's K-1/K-2, the web speed where the
//    mid-span amplitude first reaches the limit), the chuck factor k
//    (analyses/run's chuck_factor) and the Campbell sweep
//    (analyses/campbell: the order-1 backward and forward and the order-2
//    critical web speeds).
// 3. The band: every uncertain input at the low and the high end of its
//    documented range, one at a time (sampling: the forced response again;
//    the critical speeds scaled by the sample's f1, see limits_band.cpp).
// 4. The governing criterion, the safe speed and its band per diameter; for
//    a target speed, the diameter where the roll must be changed.
// 5. Warnings: the knife edge, criteria that disagree beyond their bands,
//    a mode whose label changes along the unwind.
#pragma once

#include "analyses/fit/fit.hpp"
#include "analyses/response/response.hpp"
#include "scene/limits_spec.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene.hpp"
#include "traction/traction_model.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// A limit within this fraction of a resonance peak's speed sits on a knife
// edge: a little more bow or a little less damping and the resonance itself
// decides (issue 36: 16.70 m/s against the peak at 16.74 m/s, 0.2 %).
constexpr double kKnifeEdge = 0.02;
// Between two diameters whose safe speeds differ by more than this (relative),
// the midpoint is solved too (step 1).
constexpr double kFastChange = 0.10;
// The speed range solved at each diameter, in multiples of the first critical
// web speed pi Dp f1 (f1 estimated at the beam level): above the order-1
// resonance, whose forward whirl stiffens a few per cent.
constexpr double kRangeTop = 1.3;
constexpr double kRangeBottom = 0.05;
// The band is sampled at every kBandStride-th diameter and the last; between
// them each criterion's band, relative to its point value, is interpolated
// linearly in the diameter (the ranges move the speeds by similar fractions
// along one unwind; docs/how-to/limits.md, "The band").
constexpr int kBandStride = 4;
// Speeds of the forced response's grid and of the Campbell sweep per diameter.
constexpr int kResponsePoints = 121;
constexpr int kCampbellPoints = 14;

// The criteria, in the order every table lists them.
// `traction` is the web's slip on its first idler roller (Rice & Gans,
// traction/), given when the case has a [traction] table.
enum class Criterion { i5_low, i5_high, koenig, order1_backward, order1_forward, order2, amplitude, traction };
constexpr int kCriteria = 8;
const char* criterion_id(Criterion c);    // "i5_0.7", ... (summary.json, CSV)
const char* criterion_name(Criterion c);  // "I-5 x0.7", ... (people)

struct CriterionSpeed {
    Criterion criterion = Criterion::i5_low;
    bool given = false;  // false: not at this level or not reached in the range (why: note)
    bool limits = true;  // counts toward the verdict (the order-2 line only with
                         // an order-2 load)
    double web_speed_m_s = 0;
    double band_low_m_s = 0, band_high_m_s = 0;  // = web_speed without a band
    std::string note;
    // The level that gives it, where the verdict mixes levels (a coupled
    // scene: "coupled", or "harmonic, axisymmetric equivalent (...)"); empty:
    // the verdict's level.
    std::string level;
};

struct LimitsPoint {
    double diameter_m = 0;               // the rest roll's outer diameter (the core's when bare)
    bool added = false;                  // a midpoint of step 1
    bool band_sampled = false;           // the band sampled here, or interpolated from the
                                         // sampled neighbours
    double f1_hz = 0;                    // first bending at rest, the scene's level
    std::optional<double> chuck_factor;  // k = f1 / f2 (chucks only)
    double f2_hz = 0;
    // A coupled scene: f1 of the axisymmetric equivalent the spinning
    // criteria come from (f1_hz is the coupled level's).
    std::optional<double> equivalent_f1_hz;
    std::vector<CriterionSpeed> criteria;  // kCriteria, in Criterion order
    int governing = -1;                    // index of the lowest limiting criterion given
    double safe_m_s = 0, safe_low_m_s = 0, safe_high_m_s = 0;
    std::string order1_mode;  // the label of the first order-1 crossing's mode
                              // ("bending n=1 m=0")
    std::vector<ResponsePeak> peaks;
    std::vector<std::pair<double, double>> amplitude;  // (web speed m/s, mid-span amplitude m): the orbit against
                                                       // speed
    const CriterionSpeed& at(Criterion c) const { return criteria[static_cast<int>(c)]; }
};

// One uncertain input and how far it was varied.
struct UncertainInput {
    std::string name;          // "damping ratio"
    std::string range;         // "0.005-0.02"
    std::string source;        // published source, or why the range is assumed
    double low = 0, high = 0;  // what the two samples set (SI or factors: `what`)
    std::string what;          // "zeta", "x k_n, k_t", ...
    bool applies = true;
    std::string why_not;  // when it does not apply to this scene or level
};

struct RollChange {
    double target_m_s = 0;
    bool never_safe = false;  // the target is above the safe speed already at the
                              // largest diameter
    bool needed = false;      // the safe speed falls below the target before the
                              // smallest diameter
    double diameter_m = 0;    // where it does (needed), or the smallest diameter
    double margin_m_s = 0;    // conservative safe speed at the largest diameter minus the target
};

// The one line the console ends with, and its numbers.
struct Verdict {
    double speed_m_s = 0;     // the conservative end, lowest over the unwind down to the roll change
    double diameter_m = 0;    // the roll change (or the smallest diameter)
    std::string governed_by;  // the criterion at the lowest point
    double band_low_m_s = 0, band_high_m_s = 0;
    double at_diameter_m = 0;  // where the lowest point is
};

// The forced response's checks (response.hpp), run once per verdict at the
// first diameter solved.
struct LimitsChecks {
    double diameter_m = 0;
    ResponseChecks checks;
};

struct LimitsResult {
    ModelChoice level = ModelChoice::beam;  // the model level of every criterion
    std::vector<LimitsPoint> points;  // largest diameter first
    std::vector<UncertainInput> inputs;
    bool band = true;
    double limit_m = kDefaultAmplitudeLimit;
    std::string damping_summary;
    double bow_m = 0;
    std::optional<RollChange> change;
    Verdict verdict;
    std::vector<std::string> warnings, assumptions, notes;
    std::optional<LimitsChecks> checks;
    bool check_response = true;  // as asked (LimitsRequest)
    bool campbell_sweep = true;  // as asked (LimitsRequest)
    int n_solves = 0;            // forced responses and Campbell sweeps
    double seconds = 0;
};

// What the verdict is asked: the case's [limits] (or defaults) and the
// command line's target speed (overrides [limits] web_speed).
struct LimitsRequest {
    LimitsSpec spec;
    std::optional<double> target_web_speed_m_s;
    // The uncertain inputs and their ranges; default uncertain_inputs
    // (limits_band.hpp). A narrower range (a measured damping, a fitted
    // contact stiffness) narrows the band.
    std::optional<std::vector<UncertainInput>> inputs;
    // The web speed at which the web slips on its first idler roller (the
    // case's [traction], traction_slip_criterion), or none without a roller.
    std::optional<CriterionSpeed> traction;
    // A fit of the scene to measured frequencies (`coremodal fit`; the scene
    // holds its fitted values): the ranges it narrows (narrow_by_fit), and
    // the measurements file for the output.
    std::optional<FitOutcome> fit;
    std::string fit_file;
    // Check the forced response's superposition once, at the first diameter
    // (LimitsResult::checks); `run`'s verdict line leaves it to `limits`.
    bool check_response = true;
    // Where the beam level's exact critical speeds do not apply (unlike
    // bending planes: a web, unlike supports), sweep the Campbell diagram
    // (minutes at the beam level); `run`'s verdict line does not, and says so.
    bool campbell_sweep = true;
    // A progress line per diameter solved (the command, unless -q).
    std::function<void(const std::string&)> progress;
    void say(const std::string& line) const {
        if (progress) progress(line);
    }
};

// `coremodal run` on a roll held in its stand ends with the verdict line too
// (also under -q): at the beam level and the case's roll only, without the
// band (milliseconds; `coremodal limits` gives the unwind and the band).
// Empty for a free scene; the reason instead of the line where the verdict
// cannot be had at the beam level.
std::string stand_verdict_line(const std::string& case_file);

// The traction criterion of a roller: the speed at which it can no longer
// carry the tension difference it is given ([traction] tension_difference),
// else the speed at which traction vanishes altogether (docs/how-to/traction.md).
// It does not depend on the rest roll's diameter nor on the band's inputs.
CriterionSpeed traction_slip_criterion(const TractionSpec& spec);

// The verdict for a scene held in its stand. `response`: the case's
// [damping]/[excitation]/[response] (their damping, excitation, limit and
// probes are kept; the speeds are the verdict's own), or the sourced
// defaults without. Throws InputError (before any work) for a free scene, a
// level that cannot spin or respond (naming the levels that can), a
// negative target; SolveError from the solvers.
LimitsResult verdict(const Scene& scene, const std::optional<ResponseSetup>& response, const LimitsRequest& request);

// A scene at the coupled level (segmented chucks): f1, the chuck factor k,
// I-5 and Koenig from the coupled level's modes at every diameter (what the
// pads change); the spinning criteria (critical speeds, the forced response
// and their band) from the harmonic level of the axisymmetric equivalent
// (models/coupled/axisymmetric_equivalent.hpp: the pads as a full band with
// its contact stiffness scaled by their coverage, exact for n = 1). The
// difference of the two f1 is reported, a warning where it exceeds I-5's band.
// `verdict` takes this path for a coupled scene.
LimitsResult coupled_verdict(const Scene& scene, const std::optional<ResponseSetup>& response,
                             const LimitsRequest& request);

// The checks of `verdict` before any work (InputError).
void require_limits_scene(const Scene& scene, const LimitsRequest& request);

// "safe up to X m/s at roll change, D = ... mm; governed by ...; band a-b m/s"
std::string verdict_line(const LimitsResult& r);

// The scene with its rest roll at outer diameter d (the bare core at the
// core's outer diameter); the rest paper's material is kept.
Scene scene_at_diameter(const Scene& scene, double d);

// The response setup the verdict uses at a scene without [response]:
// damping 0.01 (the middle of the measured 0.005-0.02), a half-sine bow of
// kBowPerLength times the core length, gravity, the limit at mid-span.
ResponseSetup default_limits_setup(const Scene& scene, double limit_m);
// Ilomaki: "The out of straightness of cores should generally be no more
// than +-0.5 mm/m" (On the durability of cores and rest roll dynamics).
constexpr double kBowPerLength = 0.5e-3;  // m per m of core
constexpr double kDefaultDampingRatio = 0.01;
constexpr double kDampingLow = 0.005, kDampingHigh = 0.02;

}  // namespace coremodal
