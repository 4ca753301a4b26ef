#include "analyses/campbell/campbell.hpp"
#include "models/spinning_model.hpp"

#include "analyses/campbell/zero_frequency_crossings.hpp"

#include "common/error.hpp"
#include "common/stopwatch.hpp"
#include "effects/damping.hpp"
#include "effects/rotation.hpp"
#include "models/choose.hpp"
#include "models/solid/rotating_solid.hpp"  // require_spinnable_by_solid
#include "modes/tracking.hpp"  // assign_maximum

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace coremodal {
namespace {

// The modes at one speed of the internal sweep, before tracking.
struct Step {
    double speed_hz = 0;
    std::vector<RotatingMode> modes;
    std::vector<int> tracks;
    bool reported = false;
};

// The internal sweep: rest, the continuation to the first speed, the scene's speeds.
std::vector<Step> internal_speeds(const std::vector<double>& speeds) {
    std::vector<Step> steps{{0.0, {}, {}, speeds.front() == 0.0}};
    if (speeds.front() > 0)
        for (int i = 1; i < kContinuationSteps; ++i) steps.push_back({speeds.front() * i / kContinuationSteps, {}, {}, false});
    for (double s : speeds)
        if (s > 0) steps.push_back({s, {}, {}, true});
    return steps;
}

void follow(const Step& previous, Step& current, int& next_track) {
    std::vector<std::vector<double>> weight(current.modes.size(), std::vector<double>(previous.modes.size()));
    for (size_t i = 0; i < current.modes.size(); ++i)
        for (size_t j = 0; j < previous.modes.size(); ++j)
            weight[i][j] = current.modes[i].block == previous.modes[j].block
                               ? complex_mac(current.modes[i].shape, previous.modes[j].shape)
                               : 0.0;
    const std::vector<int> match = assign_maximum(weight);
    current.tracks.assign(current.modes.size(), -1);
    for (size_t i = 0; i < current.modes.size(); ++i)
        current.tracks[i] = match[i] >= 0 && weight[i][match[i]] >= kSameModeMac ? previous.tracks[match[i]] : next_track++;
}

// Every track's label at its first speed and its first whirl.
struct TrackInfo {
    ModeLabel label;
    Whirl whirl = Whirl::none;
};

std::map<int, TrackInfo> track_info(const std::vector<Step>& steps) {
    std::map<int, TrackInfo> info;
    for (const Step& s : steps)
        for (size_t i = 0; i < s.modes.size(); ++i) {
            auto [it, fresh] = info.try_emplace(s.tracks[i], TrackInfo{s.modes[i].label, Whirl::none});
            if (it->second.whirl == Whirl::none) it->second.whirl = s.modes[i].whirl;
        }
    return info;
}

double first_bending_hz(const std::vector<RotatingMode>& rest) {
    for (const RotatingMode& m : rest)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}

// One end of a crossing's bracket: a speed, g = f_track - order f_rot there
// (> 0 below the crossing, <= 0 above), and the track's mode.
struct BracketEnd {
    double speed_hz = 0, g = 0;
    RotatingMode mode;
};

// The mode of `modes` that continues the track between the bracket's ends:
// of their block, the largest sum of the MACs with the two ends' modes (a
// planar pair at rest has MAC 1/2 with both whirls; the spinning end tells
// them apart), at least kSameModeMac with one of them; none otherwise.
const RotatingMode* continuation(const std::vector<RotatingMode>& modes, const BracketEnd& low, const BracketEnd& high) {
    const RotatingMode* best = nullptr;
    double best_sum = 0;
    for (const RotatingMode& m : modes) {
        if (m.block != low.mode.block) continue;
        const double a = complex_mac(m.shape, low.mode.shape), b = complex_mac(m.shape, high.mode.shape);
        if (std::max(a, b) >= kSameModeMac && a + b > best_sum) best = &m, best_sum = a + b;
    }
    return best;
}

// The track's mode at the sweep's step of speed `speed_hz`.
std::optional<BracketEnd> bracket_end(const std::vector<Step>& steps, double speed_hz, int track, int order) {
    for (const Step& step : steps)
        if (step.reported && step.speed_hz == speed_hz)
            for (size_t i = 0; i < step.modes.size(); ++i)
                if (step.tracks[i] == track)
                    return BracketEnd{speed_hz, step.modes[i].frequency_hz - order * speed_hz, step.modes[i]};
    return std::nullopt;
}

// Regula falsi with the Illinois modification (the g of an end that stays
// twice is halved, so that both ends close in) on g(f_rot) = f_track - k f_rot,
// each trial nudged by a fraction of the tolerance towards the end that
// stayed last, which closes the bracket in one solve once the estimate is
// that good. Keeps the interpolation (refined = false) if the track is lost.
void refine(WhirlCrossing& c, const std::vector<Step>& steps, const BlockModesAtSpeed& modes_at) {
    constexpr double kNudge = 0.4;  // of the tolerance
    std::optional<BracketEnd> low = bracket_end(steps, c.low_speed_hz, c.track, c.order);
    std::optional<BracketEnd> high = bracket_end(steps, c.high_speed_hz, c.track, c.order);
    if (!low || !high) return;
    double g_low = low->g, g_high = high->g;  // Illinois-scaled
    int last_moved = 0;                       // -1 low, +1 high
    while (high->speed_hz - low->speed_hz > kCrossingSpeedTolerance * high->speed_hz) {
        if (c.refinement_solves >= kMaxRefinementSolves) return;
        const double width = high->speed_hz - low->speed_hz, tol = kCrossingSpeedTolerance * high->speed_hz;
        double s = low->speed_hz + width * g_low / (g_low - g_high);
        s += last_moved * -kNudge * tol;  // towards the end that did not move
        s = std::clamp(s, low->speed_hz + 0.1 * tol, high->speed_hz - 0.1 * tol);
        const std::vector<RotatingMode> modes = modes_at(s, low->mode.block);
        ++c.refinement_solves;
        const RotatingMode* m = continuation(modes, *low, *high);
        if (!m) return;
        const BracketEnd end{s, m->frequency_hz - c.order * s, *m};
        if (end.g > 0) {
            if (last_moved == -1) g_high /= 2;
            low = end, g_low = end.g, last_moved = -1;
        } else {
            if (last_moved == +1) g_low /= 2;
            high = end, g_high = end.g, last_moved = +1;
        }
    }
    const double speed = low->speed_hz + (high->speed_hz - low->speed_hz) * low->g / (low->g - high->g);
    c.low_speed_hz = low->speed_hz;
    c.high_speed_hz = high->speed_hz;
    c.speed_hz = speed;
    c.frequency_hz = c.order * speed;
    c.refined = true;
}

// Each reported mode's damped partner (or none) into the point.
void add_damping(CampbellPoint& point, const std::vector<std::optional<DampedPartner>>& partners, CampbellResult& out) {
    for (size_t i = 0; i < point.modes.size(); ++i) {
        if (!partners[i]) continue;
        point.modes[i].damping_ratio = partners[i]->damping_ratio;
        point.modes[i].damped_frequency_hz = partners[i]->damped_frequency_hz;
        out.max_damped_residual = std::max(out.max_damped_residual, partners[i]->relative_residual);
    }
}

}  // namespace

void campbell_sweep(const std::vector<RotatingMode>& at_rest, size_t reported, const ModesAtSpeed& modes_at,
                    const RotationSpec& rotation, CampbellResult& out, const LabelMode& label_new_track,
                    const BlockModesAtSpeed& block_modes_at, const DampedPartners& damped_partners) {
    std::vector<Step> steps = internal_speeds(rotation.speeds_hz);
    int next_track = 1;
    for (size_t s = 0; s < steps.size(); ++s) {
        Step& step = steps[s];
        step.modes = s == 0 ? at_rest : modes_at(step.speed_hz);
        if (s == 0) {
            for (size_t i = 0; i < step.modes.size(); ++i) step.tracks.push_back(next_track++);
            continue;
        }
        const int first_new_track = next_track;
        follow(steps[s - 1], step, next_track);
        if (label_new_track)
            for (size_t i = 0; i < step.modes.size(); ++i)
                if (step.tracks[i] >= first_new_track) step.modes[i].label = label_new_track(step.modes[i]);
    }
    const std::map<int, TrackInfo> info = track_info(steps);
    for (const Step& step : steps) {
        if (!step.reported) continue;
        CampbellPoint point{step.speed_hz, {}};
        const size_t n_reported = std::min(reported, step.modes.size());
        for (size_t i = 0; i < n_reported; ++i) {
            const RotatingMode& m = step.modes[i];
            const TrackInfo& track = info.at(step.tracks[i]);
            point.modes.push_back({step.tracks[i], m.frequency_hz, m.whirl == Whirl::none ? track.whirl : m.whirl,
                                   track.label, m.relative_residual});
            out.max_relative_residual = std::max(out.max_relative_residual, m.relative_residual);
        }
        if (damped_partners) add_damping(point, damped_partners(step.speed_hz, {step.modes.begin(), step.modes.begin() + n_reported}), out);
        out.points.push_back(std::move(point));
    }
    out.critical = critical_speeds(out.points, out.excitation_orders, out.roll_outer_diameter);
    const BlockModesAtSpeed refine_with =
        block_modes_at ? block_modes_at : [&](double speed, int) { return modes_at(speed); };
    for (WhirlCrossing& c : out.critical) {
        refine(c, steps, refine_with);
        c.web_speed_m_s = web_speed(c.speed_hz, out.roll_outer_diameter);
    }
    std::sort(out.critical.begin(), out.critical.end(),
              [](const WhirlCrossing& x, const WhirlCrossing& y) { return x.speed_hz < y.speed_hz; });
}

void require_spinning_level(const Scene& scene) {
    // A chuck not expanded (auto picks the coupled level at rest): only the
    // solid could spin the scene, and it refuses why (time-periodic).
    const LevelTraits& level = level_traits(chosen_spinning_level(scene));
    if (!level.spins) throw cannot_spin(scene, level.level);
    if (level.spins_in_rotating_frame) require_spinnable_by_solid(scene);
}

void require_campbell_damping(const Scene& scene, const DampingSpec& damping) {
    const LevelTraits& level = level_traits(chosen_spinning_level(scene));
    if (!level.campbell_damping)
        throw InputError(scene.source_file + ": [damping] in a Campbell sweep at model = \"" + to_string(level.level) +
                         "\": only the harmonic level's operator sets carry damping today; expected model = "
                         "\"harmonic\" (or --model harmonic) for a body of revolution, or no [damping]");
    const bool modal = damping.ratio > 0 || !damping.families.empty() || !damping.modes.empty();
    if (modal)
        throw InputError(scene.source_file + ": " +
                         (damping.ratio > 0 ? damping.source : std::string("[damping] a family's or a mode's ratio")) +
                         ": a modal ratio belongs to the modes at rest, which the spin mixes; a Campbell sweep takes "
                         "damping as terms of the operators; expected " + kOperatorDampingKeys +
                         " (docs/how-to/campbell.md)");
}

namespace {

// Which damping entered the sweep, from which keys, echoed in the report.
std::vector<std::string> damping_words(const DampingSpec& d) {
    std::vector<std::string> out = operator_damping_words(d);
    out.push_back("damped modes: per wave number the projected damped problem (the basis of the modes at rest and "
                  "their static responses to D, H and the spin's forces), each matched to the undamped mode of "
                  "largest MAC; zeta = -Re lambda / |lambda|, damped frequency Im lambda / (2 pi); the critical "
                  "speeds are the undamped sweep's (light damping moves a crossing by O(zeta^2))");
    return out;
}

// What the result says before the sweep: the scene's speeds and lines, the
// level, the terms included.
CampbellResult campbell_header(const Scene& scene, const RotationSpec& rotation, const DampingSpec* damping) {
    CampbellResult out;
    out.excitation_orders = rotation.excitation_orders;
    out.roll_outer_diameter = roll_outer_diameter(scene);
    out.from_web_speed = rotation.from_web_speed;
    out.operating_hz = rotation.operating_hz;
    const LevelTraits& level = level_traits(chosen_spinning_level(scene));
    out.effects = rotating_effect_names(scene, rotation, level.centrifugal);
    out.level = level.level;
    if (damping) {
        out.damped = true;
        out.damping = damping_words(*damping);
        for (std::string& e : operator_damping_effects(*damping)) out.effects.push_back(std::move(e));
    }
    return out;
}

}  // namespace

const WhirlCrossing* CampbellResult::first_order_one() const {
    for (const WhirlCrossing& c : critical)
        if (c.order == 1) return &c;
    return nullptr;
}

std::vector<const WhirlCrossing*> CampbellResult::inside_operating_range() const {
    std::vector<const WhirlCrossing*> out;
    if (!operating_hz) return out;
    for (const WhirlCrossing& c : critical)
        if (c.speed_hz >= (*operating_hz)[0] && c.speed_hz <= (*operating_hz)[1]) out.push_back(&c);
    return out;
}

std::vector<WhirlCrossing> critical_speeds(const std::vector<CampbellPoint>& points, const std::vector<int>& orders,
                                           double dp) {
    std::vector<WhirlCrossing> out;
    for (size_t p = 0; p + 1 < points.size(); ++p)
        for (const CampbellMode& a : points[p].modes) {
            if (a.label.type == "rigid" || a.frequency_hz <= 0) continue;
            const auto b = std::find_if(points[p + 1].modes.begin(), points[p + 1].modes.end(),
                                        [&](const CampbellMode& m) { return m.track == a.track; });
            if (b == points[p + 1].modes.end()) continue;
            const double s0 = points[p].speed_hz, s1 = points[p + 1].speed_hz;
            for (int k : orders) {
                const double g0 = a.frequency_hz - k * s0, g1 = b->frequency_hz - k * s1;
                if (!(g0 > 0 && g1 <= 0)) continue;  // the line rises through the curve
                const double t = g0 / (g0 - g1), speed = s0 + t * (s1 - s0);
                WhirlCrossing c{k, a.track, b->whirl, a.label, speed, k * speed, web_speed(speed, dp)};
                c.low_speed_hz = s0;
                c.high_speed_hz = s1;
                c.interpolated_speed_hz = speed;
                out.push_back(c);
            }
        }
    std::sort(out.begin(), out.end(), [](const WhirlCrossing& x, const WhirlCrossing& y) { return x.speed_hz < y.speed_hz; });
    return out;
}

CampbellResult run_campbell(const Scene& scene, const RotationSpec& rotation, const DampingSpec* damping) {
    COREMODAL_ASSERT(!rotation.speeds_hz.empty());
    require_spinning_level(scene);
    if (damping) require_campbell_damping(scene, *damping);
    Stopwatch clock;
    CampbellResult out = campbell_header(scene, rotation, damping);
    // The level's spinning model (its terms live with it, models/<level>/);
    // require_spinning_level refused a level that cannot spin.
    const std::unique_ptr<SpinningModel> model =
        make_model_level(out.level)->spinning(scene, {rotation, kExtraTrackedModes, damping});
    out.notes = model->notes();
    out.n_dofs = model->n_dofs();
    // Co-rotating coordinates: the exact critical speeds of the pencils
    // first, and a sweep that ends below the lowest (zero_frequency_crossings.hpp).
    ZeroFrequencyPlan plan{rotation, {}, {}, {}};
    if (const ZeroFrequencyPencils* pencils = model->zero_frequency_pencils())
        plan = plan_zero_frequency_sweep(*pencils, rotation, out.roll_outer_diameter);
    const std::vector<RotatingMode> at_rest = model->modes_at_rest();
    const double f1 = first_bending_hz(at_rest);
    out.speeds_at_rest = roll_speeds(scene, f1, f1 > 0 ? "" : "no bending mode");
    campbell_sweep(
        at_rest, model->reported(), [&](double speed) { return model->modes_at(speed); }, plan.swept, out,
        model->label_new_track(), model->block_modes_at(), model->damped_partners());
    merge_pencil_crossings(out, plan.crossings);
    out.notes.insert(out.notes.end(), plan.notes.begin(), plan.notes.end());
    out.sweep_end = plan.sweep_end;
    if (!plan.sweep_end.empty()) out.notes.push_back(plan.sweep_end);
    for (std::string& note : model->notes_after_sweep()) out.notes.push_back(std::move(note));
    out.solver = model->solver();
    out.completeness = model->completeness();
    out.solve_seconds = clock.lap();
    return out;
}

}  // namespace coremodal
