#include "analyses/campbell/campbell.hpp"

#include "common/error.hpp"
#include "common/stopwatch.hpp"
#include "effects/rotation.hpp"
#include "modes/tracking.hpp"  // assign_maximum

#include <algorithm>
#include <cmath>
#include <map>

namespace coremodal {
namespace {

// The modes at one speed of the internal sweep, before tracking.
struct Step {
    double speed_hz = 0;
    std::vector<RotatingMode> modes;
    std::vector<int> tracks;
    bool reported = false;
};

std::vector<RotatingMode> modes_at_rest(const BeamModelResult& rest) {
    std::vector<RotatingMode> out;
    for (const BeamMode& m : rest.modes) {
        RotatingMode r;
        r.frequency_hz = m.frequency_hz;
        r.label = m.label;
        r.relative_residual = m.relative_residual;
        r.shape = m.shape.cast<std::complex<double>>();
        out.push_back(std::move(r));
    }
    return out;
}

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
            weight[i][j] = complex_mac(current.modes[i].shape, previous.modes[j].shape);
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

std::vector<std::string> rotation_notes(const RotationSpec& rotation) {
    std::vector<std::string> notes{
        "rotation at the beam level: the gyroscopic term of every spinning beam (core with rest paper, chuck bodies "
        "and shafts; polar inertia rho_J per length); bearings and frames do not spin"};
    if (rotation.centrifugal_stiffening)
        notes.push_back(
            "[rotation] centrifugal_stiffening = true: not included at the beam level, which has no term for it (the "
            "hoop prestress of a spinning roll stiffens its section's ovalling, not its bending; zero in beam theory)");
    return notes;
}

double first_bending_hz(const BeamModelResult& rest) {
    for (const BeamMode& m : rest.modes)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}

}  // namespace

const WhirlCrossing* CampbellResult::first_order_one() const {
    for (const WhirlCrossing& c : critical)
        if (c.order == 1) return &c;
    return nullptr;
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
                out.push_back({k, a.track, b->whirl, a.label, speed, k * speed, web_speed(speed, dp)});
            }
        }
    std::sort(out.begin(), out.end(), [](const WhirlCrossing& x, const WhirlCrossing& y) { return x.speed_hz < y.speed_hz; });
    return out;
}

CampbellResult run_campbell(const Scene& scene, const RotationSpec& rotation, const BeamModelOptions& options) {
    COREMODAL_ASSERT(!rotation.speeds_hz.empty());
    if (scene.model != "beam")
        throw InputError(scene.source_file + ": [rotation] is simulated at the beam level only so far; expected model = \"beam\" "
                                             "(or --model beam); the solid and harmonic levels have no gyroscopic term yet");
    Stopwatch clock;
    CampbellResult out;
    out.excitation_orders = rotation.excitation_orders;
    out.roll_outer_diameter = roll_outer_diameter(scene);
    out.from_web_speed = rotation.from_web_speed;
    out.effects = rotating_effect_names(scene, rotation);
    out.notes = rotation_notes(rotation);
    out.rest = solve_beam_model(scene, options);
    out.speeds_at_rest = roll_speeds(scene, first_bending_hz(out.rest), first_bending_hz(out.rest) > 0 ? "" : "no bending mode");
    const RotatingNetwork network(out.rest.network, out.rest.lambda_scale);
    out.n_dofs = network.n_free_dofs();
    const size_t reported = out.rest.modes.size(), window = reported + kExtraTrackedModes;

    std::vector<Step> steps = internal_speeds(rotation.speeds_hz);
    int next_track = 1;
    for (size_t s = 0; s < steps.size(); ++s) {
        Step& step = steps[s];
        step.modes = s == 0 ? modes_at_rest(out.rest) : network.modes_at(step.speed_hz, static_cast<int>(window));
        if (s == 0) {
            for (size_t i = 0; i < step.modes.size(); ++i) step.tracks.push_back(next_track++);
        } else {
            follow(steps[s - 1], step, next_track);
        }
    }
    const std::map<int, TrackInfo> info = track_info(steps);
    for (const Step& step : steps) {
        if (!step.reported) continue;
        CampbellPoint point{step.speed_hz, {}};
        for (size_t i = 0; i < std::min(reported, step.modes.size()); ++i) {
            const RotatingMode& m = step.modes[i];
            const TrackInfo& track = info.at(step.tracks[i]);
            point.modes.push_back({step.tracks[i], m.frequency_hz, m.whirl == Whirl::none ? track.whirl : m.whirl,
                                   track.label, m.relative_residual});
            out.max_relative_residual = std::max(out.max_relative_residual, m.relative_residual);
        }
        out.points.push_back(std::move(point));
    }
    out.critical = critical_speeds(out.points, out.excitation_orders, out.roll_outer_diameter);
    out.solve_seconds = clock.lap();
    return out;
}

}  // namespace coremodal
