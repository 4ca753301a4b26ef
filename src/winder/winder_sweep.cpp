#include "winder/winder_sweep.hpp"

#include "common/error.hpp"
#include "common/stopwatch.hpp"
#include "modes/tracking.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace coremodal {
namespace {

// One solved diameter, as tracking sees it.
struct TrackedPoint {
    std::vector<ModeGroup> groups;
    std::vector<int> group_track;
};

std::vector<ModeSummary> summaries(const WinderModel& model, const WinderModes& modes) {
    std::vector<ModeSummary> out;
    for (int i = 0; i < modes.n_reported; ++i) {
        ModeSummary s;
        s.index = i + 1;
        s.frequency_hz = modes.modes[i].frequency_hz;
        // n = 0: only truly equal frequencies make a group (tracking.hpp).
        s.label.type = body_kind_name(modes.modes[i].type);
        s.signature = mode_signature(model, modes.shapes.col(i));
        out.push_back(std::move(s));
    }
    return out;
}

SweepPoint point_of(const WinderModel& model, const WinderModes& modes, const WinderScene& scene, int dof) {
    SweepPoint p;
    p.roll_diameter = model.state.geometry.roll_diameter;
    p.state = model.state;
    p.verification = modes.verification;
    p.estimate = estimate_drum_frequency(model, modes);
    for (int i = 0; i < modes.n_reported; ++i) {
        const WinderMode& m = modes.modes[i];
        SweepMode s;
        s.index = i + 1, s.frequency_hz = m.frequency_hz, s.type = m.type;
        s.kinetic_share = m.kinetic_share, s.damping_ratio = m.damping_ratio;
        p.modes.push_back(s);
    }
    for (int k = 1; k <= scene.sweep.harmonics; ++k)
        p.harmonic_response.push_back(std::abs(receptance(modes, dof, roll_harmonic_hz(k, scene.web_speed, p.roll_diameter))));
    return p;
}

// Track ids, MAC and ambiguity of each mode of `point` from its groups' steps.
void apply_steps(const std::vector<ModeGroup>& groups, const std::vector<TrackStep>& steps, SweepPoint& point,
                 TrackedPoint& tracked) {
    tracked.groups = groups;
    tracked.group_track.clear();
    for (size_t g = 0; g < groups.size(); ++g) {
        tracked.group_track.push_back(steps[g].track);
        for (int member : groups[g].members) {
            SweepMode& m = point.modes[member];
            m.track = steps[g].track, m.mac_previous = steps[g].mac_previous, m.ambiguous = steps[g].ambiguous;
        }
    }
}

std::vector<TrackSeries> track_series(const std::vector<SweepPoint>& points) {
    std::map<int, TrackSeries> by_track;
    const size_t n = points.size();
    for (size_t i = 0; i < n; ++i)
        for (const SweepMode& m : points[i].modes) {
            TrackSeries& t = by_track[m.track];
            if (t.frequency_hz.empty()) t.track = m.track, t.frequency_hz.resize(n), t.drum.resize(n, false);
            if (t.frequency_hz[i]) continue;  // a degenerate group: its first member stands for it
            t.frequency_hz[i] = m.frequency_hz;
            t.drum[i] = m.type == BodyKind::drum;
        }
    std::vector<TrackSeries> out;
    for (auto& [id, t] : by_track) out.push_back(std::move(t));
    return out;
}

// The crossing's mode at its own diameter: the group most like the track's
// group at the nearer sweep point (MAC), its resonance X/F.
void resolve_crossing(const WinderScene& scene, const std::vector<double>& d, const std::vector<TrackedPoint>& tracked,
                      int dof, Crossing& c) {
    size_t near = 0;
    for (size_t i = 0; i < d.size(); ++i)
        if (std::abs(1 / d[i] - 1 / c.roll_diameter) < std::abs(1 / d[near] - 1 / c.roll_diameter)) near = i;
    const auto& tp = tracked[near];
    const auto it = std::find(tp.group_track.begin(), tp.group_track.end(), c.track);
    COREMODAL_ASSERT(it != tp.group_track.end());
    const ModeGroup& reference = tp.groups[it - tp.group_track.begin()];
    const WinderModel model = build_winder_model(scene, c.roll_diameter);
    const WinderModes modes = solve_winder_modes(model, scene.damping, scene.sweep.max_frequency);
    const std::vector<ModeGroup> groups = group_modes(summaries(model, modes));
    double best = -1;
    int mode = 0;
    for (const ModeGroup& g : groups)
        if (const double mac = group_mac(g, reference); mac > best) best = mac, mode = g.members.front();
    const WinderMode& m = modes.modes[mode];
    c.mode_frequency_hz = m.frequency_hz, c.type = m.type, c.damping_ratio = m.damping_ratio;
    c.resonance_response = std::abs(receptance(modes, dof, m.frequency_hz));
}

}  // namespace

double roll_harmonic_hz(int k, double web_speed, double roll_diameter) { return k * web_speed / (M_PI * roll_diameter); }

std::vector<double> sweep_diameters(const WinderScene& scene) {
    const int n = scene.sweep.points;
    const double a = scene.rolls.diameter_start, b = scene.rolls.diameter_end;
    std::vector<double> d;
    for (int i = 0; i < n; ++i) d.push_back(i == n - 1 ? b : a + (b - a) * i / (n - 1));
    return d;
}

std::vector<Crossing> find_crossings(const std::vector<double>& d, const std::vector<TrackSeries>& tracks,
                                     double web_speed, int harmonics) {
    std::vector<Crossing> out;
    for (const TrackSeries& t : tracks)
        for (size_t i = 0; i + 1 < d.size(); ++i) {
            if (!t.frequency_hz[i] || !t.frequency_hz[i + 1] || !(t.drum[i] || t.drum[i + 1])) continue;
            for (int k = 1; k <= harmonics; ++k) {
                const double g0 = *t.frequency_hz[i] - roll_harmonic_hz(k, web_speed, d[i]);
                const double g1 = *t.frequency_hz[i + 1] - roll_harmonic_hz(k, web_speed, d[i + 1]);
                // A touch at a point counts once: at its left interval, or at the last point.
                const bool at_end = g1 == 0 && i + 2 == d.size();
                if (!((g0 < 0 && g1 > 0) || (g0 > 0 && g1 < 0) || g0 == 0 || at_end)) continue;
                const double t_share = g0 == g1 ? 0.0 : g0 / (g0 - g1);
                const double u = 1 / d[i] + t_share * (1 / d[i + 1] - 1 / d[i]);  // 1/d
                Crossing c;
                c.roll_diameter = 1 / u, c.frequency_hz = k * web_speed * u / M_PI, c.harmonic = k, c.track = t.track;
                out.push_back(c);
            }
        }
    std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) {
        return a.roll_diameter < b.roll_diameter || (a.roll_diameter == b.roll_diameter && a.harmonic < b.harmonic);
    });
    return out;
}

WinderSweepResult run_winder_sweep(const WinderScene& scene, const std::function<void(int, int)>& progress) {
    Stopwatch clock;
    WinderSweepResult result;
    const std::vector<double> d = sweep_diameters(scene);
    std::vector<TrackedPoint> tracked(d.size());
    int next_track = 1;
    for (size_t i = 0; i < d.size(); ++i) {
        const WinderModel model = build_winder_model(scene, d[i]);
        if (i == 0) {
            result.response_dof = response_dof(model, scene.sweep.response_drum, scene.sweep.response_direction);
            result.n_dofs = model.n_dofs();
        }
        const WinderModes modes = solve_winder_modes(model, scene.damping, scene.sweep.max_frequency);
        SweepPoint point = point_of(model, modes, scene, result.response_dof);
        const std::vector<ModeGroup> groups = group_modes(summaries(model, modes));
        const std::vector<TrackStep> steps =
            i == 0 ? start_tracks(groups, next_track)
                   : follow_tracks(tracked[i - 1].groups, tracked[i - 1].group_track, groups, next_track);
        apply_steps(groups, steps, point, tracked[i]);
        result.points.push_back(std::move(point));
        if (progress) progress(static_cast<int>(i) + 1, static_cast<int>(d.size()));
    }
    result.crossings = find_crossings(d, track_series(result.points), scene.web_speed, scene.sweep.harmonics);
    for (Crossing& c : result.crossings) resolve_crossing(scene, d, tracked, result.response_dof, c);
    result.time_s = clock.seconds();
    return result;
}

}  // namespace coremodal
