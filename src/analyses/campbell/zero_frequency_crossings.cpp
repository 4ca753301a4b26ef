#include "analyses/campbell/zero_frequency_crossings.hpp"
#include "models/spinning_model.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "common/stopwatch.hpp"
#include "effects/rotation.hpp"
#include "modes/tracking.hpp"  // label_text

#include <algorithm>
#include <cmath>
#include <ctime>

namespace coremodal {
namespace {

std::string rpm_text(double speed_hz) { return significant(speed_hz * 60, 6) + " rpm"; }

WhirlCrossing pencil_crossing(const ZeroFrequencyMode& m, double dp) {
    WhirlCrossing c;
    c.order = m.order;
    c.track = 0;  // not on a tracked curve of the sweep
    c.whirl = m.whirl;
    c.label = m.label;
    c.speed_hz = c.low_speed_hz = c.high_speed_hz = c.interpolated_speed_hz = m.speed_hz;
    c.frequency_hz = m.order * m.speed_hz;
    c.web_speed_m_s = web_speed(m.speed_hz, dp);
    c.refined = true;
    c.source = CrossingSource::pencil;
    return c;
}

// What the pencil found, in words, for the notes.
// wall and cpu: the pencil's seconds (the inertia count and the solve; CPU of the process, all threads).
std::string count_note(const ZeroFrequencyModes& z, double wall, double cpu) {
    std::string s = "critical speeds from the pencil (exact): the speeds below " + rpm_text(z.max_speed_hz) +
                    " where a mode's rotating-frame frequency is zero are the eigenvalues Omega^2 of K x = Omega^2 "
                    "(M_P - K_sigma1) x; the inertia of K(Omega) at " + rpm_text(z.max_speed_hz) + " counts " +
                    std::to_string(z.counted) + " (Sylvester's law, K positive definite: a proof, up to the LDL^T's "
                    "rounding) and " + std::to_string(z.counted) + " were found (" + significant(wall, 3) + " s wall, " + significant(cpu, 3) +
                    " s CPU)";
    double smallest_share = 1;
    for (const ZeroFrequencyMode& m : z.modes) {
        smallest_share = std::min(smallest_share, m.share);
        if (m.multiplicity > 1) s += "; " + rpm_text(m.speed_hz) + " twice (a pair: one forward crossing)";
    }
    if (!z.modes.empty())
        s += "; each is a forward crossing of the order |k| of its null vector's dominant harmonic k on the roll's "
             "surface (smallest share " + significant(smallest_share, 3) + "); critical speeds with source "
             "\"pencil\" come from it, those with source \"sweep\" from the sweep's speeds (refined or interpolated)";
    return s;
}

// A zero-frequency speed that is no crossing of a requested order: said in the notes.
std::string other_speed_note(const ZeroFrequencyMode& m) {
    if (m.wave_number == 0)
        return "at " + rpm_text(m.speed_hz) + " a mode of harmonic 0 (" + label_text(m.label) +
               ") has zero frequency in both frames: a static divergence of the spinning roll, not a crossing";
    return "the pencil's speed " + rpm_text(m.speed_hz) + " is a forward crossing of order " +
           std::to_string(m.wave_number) + " (" + label_text(m.label) + "), not among [rotation] excitation_orders";
}

std::string sweep_end_text(const RotationSpec& rotation, const RotationSpec& swept, double limit_hz) {
    const size_t dropped = rotation.speeds_hz.size() - swept.speeds_hz.size();
    const double first = rotation.speeds_hz[swept.speeds_hz.size()], last = rotation.speeds_hz.back();
    const std::string which = dropped == 1 ? "the scene's last speed, " + rpm_text(last) + ", lies"
                                           : std::to_string(dropped) + " of the scene's speeds (" + rpm_text(first) +
                                                 " to " + rpm_text(last) + ") lie";
    return "the sweep stopped at " + rpm_text(swept.speeds_hz.back()) + ": " + which + " at or above " +
           significant(kSweepEndBelowZeroFrequency, 2) + " of " + rpm_text(limit_hz) +
           ", the lowest speed where a mode's rotating-frame frequency is zero; above that speed the stiffness "
           "K + Omega^2 (K_sigma1 - M_P) is indefinite and the gyroscopic solver's inertia count cannot prove a "
           "speed's modes complete (docs/theory/rotation-solid.md). The crossings above the sweep's end come from the pencils "
           "only: every order asked of modes with harmonics |k| <= " + std::to_string(kMaxCrossingHarmonic) +
           " (and forward ones of order |k| for every k); other modes' crossings are not reported there";
}

bool wanted(const RotationSpec& rotation, int order) {
    const auto& orders = rotation.excitation_orders;
    return order > 0 && std::find(orders.begin(), orders.end(), order) != orders.end();
}

// The pencil of ratio r > 0 in the notes: its count and what it gave.
std::string ratio_note(const ZeroFrequencyModes& z, size_t n_crossings, double wall, double cpu) {
    return "the pencil r = " + std::to_string(z.ratio) + " (a mode at rotating-frame frequency " +
           std::to_string(z.ratio) + " f_rot, K x = Omega^2 (M_P - K_sigma1 + r^2 M - i r G_c) x, in its real form of "
           "twice the size): the inertia at " + rpm_text(z.max_speed_hz) + " counts " + std::to_string(z.counted) +
           ", all found (" + significant(wall, 3) + " s wall, " + significant(cpu, 3) + " s CPU); crossings of an "
           "excitation line asked for (order |r - k|, k the dominant signed harmonic) among them: " +
           std::to_string(n_crossings);
}

// Adds the crossings of the pencils r > 0 to the plan.
void add_ratio_crossings(const ZeroFrequencyPencils& pencils, const RotationSpec& rotation, double dp,
                         ZeroFrequencyPlan& plan) {
    for (int r : crossing_ratios(rotation.excitation_orders)) {
        const Stopwatch clock;
        const std::clock_t cpu = std::clock();
        const ZeroFrequencyModes z = pencils.frequency_ratio_modes(rotation.speeds_hz.back(), r);
        size_t n = 0;
        for (const ZeroFrequencyMode& m : z.modes)
            if (m.whirl != Whirl::none || m.harmonic == 0)
                if (wanted(rotation, m.order)) plan.crossings.push_back(pencil_crossing(m, dp)), ++n;
        plan.notes.push_back(ratio_note(z, n, clock.seconds(), double(std::clock() - cpu) / CLOCKS_PER_SEC));
    }
}

// Keeps the scene's speeds below kSweepEndBelowZeroFrequency of the lowest
// zero-frequency speed; SolveError when none above 0 is left.
void end_sweep_below(const RotationSpec& rotation, const ZeroFrequencyMode& lowest, ZeroFrequencyPlan& plan) {
    const double limit_hz = lowest.speed_hz;
    std::erase_if(plan.swept.speeds_hz, [&](double s) { return s >= kSweepEndBelowZeroFrequency * limit_hz; });
    if (plan.swept.speeds_hz.empty())
        throw SolveError("every [rotation] speed lies at or above " + significant(kSweepEndBelowZeroFrequency, 2) +
                         " of " + rpm_text(limit_hz) + ", where a mode's rotating-frame frequency is zero (a forward "
                         "critical speed of order " + std::to_string(lowest.wave_number) +
                         "); in co-rotating coordinates no modes are proven complete above it. Start the speeds "
                         "below it (from 0 rpm: the critical speeds above are then reported from the pencils)");
    if (plan.swept.speeds_hz.size() < rotation.speeds_hz.size())
        plan.sweep_end = sweep_end_text(rotation, plan.swept, limit_hz);
}

}  // namespace

const char* crossing_source_name(CrossingSource s) { return s == CrossingSource::pencil ? "pencil" : "sweep"; }

ZeroFrequencyPlan plan_zero_frequency_sweep(const ZeroFrequencyPencils& pencils, const RotationSpec& rotation,
                                            double dp) {
    ZeroFrequencyPlan plan;
    plan.swept = rotation;
    const Stopwatch clock;
    const std::clock_t cpu = std::clock();
    const ZeroFrequencyModes z = pencils.zero_frequency_modes(rotation.speeds_hz.back());
    plan.notes.push_back(count_note(z, clock.seconds(), double(std::clock() - cpu) / CLOCKS_PER_SEC));
    for (const ZeroFrequencyMode& m : z.modes) {
        if (m.wave_number > 0 && wanted(rotation, m.wave_number))
            plan.crossings.push_back(pencil_crossing(m, dp));
        else
            plan.notes.push_back(other_speed_note(m));
    }
    if (!z.modes.empty()) end_sweep_below(rotation, z.modes.front(), plan);
    add_ratio_crossings(pencils, rotation, dp, plan);
    return plan;
}

// |r - k| = j with r >= 0 and |k| = n: r = j - n (k = -n, forward),
// n - j (k = +n, forward) or n + j (k = +n, backward).
std::vector<int> crossing_ratios(const std::vector<int>& orders) {
    std::vector<int> out;
    for (int j : orders)
        for (int n = 0; n <= kMaxCrossingHarmonic; ++n)
            for (int r : {j - n, n - j, n + j})
                if (r > 0) out.push_back(r);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

void merge_pencil_crossings(CampbellResult& out, const std::vector<WhirlCrossing>& pencil) {
    if (pencil.empty()) return;
    for (const WhirlCrossing& p : pencil)
        std::erase_if(out.critical, [&](const WhirlCrossing& c) {
            return c.source == CrossingSource::sweep && c.order == p.order && c.whirl == p.whirl &&
                   std::abs(c.speed_hz - p.speed_hz) <= kSameCrossingSpeed * p.speed_hz;
        });
    out.critical.insert(out.critical.end(), pencil.begin(), pencil.end());
    std::sort(out.critical.begin(), out.critical.end(),
              [](const WhirlCrossing& x, const WhirlCrossing& y) { return x.speed_hz < y.speed_hz; });
}

}  // namespace coremodal
