// Critical speeds of a Campbell sweep in co-rotating coordinates (a level's
// ZeroFrequencyPencils, models/spinning_model.hpp: the solid level's rotating
// frame, models/solid/rotating_frame.hpp; docs/theory/rotation-solid.md
// "Critical speeds in co-rotating coordinates").
//
// Above the lowest speed where a mode's rotating-frame frequency is zero,
// K(Omega) = K + Omega^2 (K_sigma1 - M_P) is indefinite and the gyroscopic
// solver cannot prove a speed's modes complete (it refuses). Those speeds
// are themselves critical speeds, exactly: the eigenvalues Omega^2 of the
// pencil (K, M_P - K_sigma1), each a forward crossing of the excitation
// line of order |k| (k the null vector's dominant harmonic). So before the
// sweep the pencil is solved up to the scene's last speed; the sweep is
// ended below its lowest speed, and its crossings are reported beside the
// sweep's own. The other crossings (backward, and orders other than |k|)
// come from the pencils (K, B_r) of a rotating-frame frequency r f_rot, one
// per r that a wanted order j and a harmonic |k| <= kMaxCrossingHarmonic
// need (|r - k| = j): exact, and in place of the sweep's where both have one.
#pragma once

#include "analyses/campbell/campbell.hpp"
#include "models/spinning_model.hpp"
#include "scene/rotation_spec.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The sweep ends below this share of the lowest speed of zero rotating-frame
// frequency: there a forward whirl's rotating-frame frequency is about
// (1 - share) of its own, and nearer it would fall under the gyroscopic
// solver's rigid line (1 % of the first frequency's scale), where a mode is
// reported at 0 Hz.
constexpr double kSweepEndBelowZeroFrequency = 0.98;
// The largest |k| whose crossings of every wanted order the pencils r > 0
// cover: the bending pair (k = +-1) and harmonic 0. Each r costs one
// pencil of twice the size (bench/results/log.md); ovalling (|k| = 2) lies
// far above a core's operating speeds.
constexpr int kMaxCrossingHarmonic = 1;
// A sweep crossing of the same order and whirl within this share of a
// pencil crossing's speed is the same crossing; the pencil's (exact) is kept.
constexpr double kSameCrossingSpeed = 1e-3;

struct ZeroFrequencyPlan {
    RotationSpec swept;                  // the scene's speeds below the limit (all of them when none is below)
    std::vector<WhirlCrossing> crossings; // source pencil, orders among rotation.excitation_orders
    std::vector<std::string> notes;      // the pencil's count, and its speeds of other orders
    std::string sweep_end;               // empty when the sweep keeps every speed
};

// The pencil up to the scene's last speed and the sweep that stays below its
// lowest speed. SolveError when no speed of the scene above 0 is left to
// sweep (naming the critical speed).
ZeroFrequencyPlan plan_zero_frequency_sweep(const ZeroFrequencyPencils& pencils, const RotationSpec& rotation,
                                            double roll_outer_diameter);

// The ratios r > 0 at which a mode of harmonic |k| <= kMaxCrossingHarmonic
// meets an excitation line of one of `orders` (|r - k| = j), ascending:
// one pencil each; r = 0, the zero-frequency pencil, is solved first anyway.
std::vector<int> crossing_ratios(const std::vector<int>& orders);

// Adds the pencils' crossings to out.critical (the sweep's), dropping a
// sweep crossing that is the same one (order and whirl, kSameCrossingSpeed),
// ascending by speed (out.critical untouched when `pencil` is empty).
void merge_pencil_crossings(CampbellResult& out, const std::vector<WhirlCrossing>& pencil);

}  // namespace coremodal
