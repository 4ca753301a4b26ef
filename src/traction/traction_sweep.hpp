// Rice & Gans' traction model over a range of web speeds, beside the same
// roller without its grooves: what `coremodal traction` reports
// (docs/how-to/traction.md).
#pragma once

#include "traction/traction_model.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The same roller without grooves, for the groove's gain: its clearance is
// the asperity height alone, h_eff = alpha {6}.
struct PlainRollerComparison {
    double clearance = 0;            // m, alpha (0: no air path at all, no traction at any speed above 0)
    double zero_traction_speed = 0;  // m/s
    std::vector<double> traction;    // N/m at each speed of the sweep
    std::vector<double> effective_friction;
};

struct TractionSweep {
    EffectiveClearance clearance;
    std::vector<TractionPoint> points;  // one per web speed, in order
    double zero_traction_speed = 0;     // m/s: P* = 1
    double centripetal_limit_speed = 0; // m/s: T_0 = c rho V^2 (infinite for a massless web)
    std::optional<double> slip_speed;   // m/s: when spec.tension_difference is set
    std::optional<PlainRollerComparison> plain;  // grooved rollers only
    int n_invalid = 0;                  // points outside the paper's validity limits
    int n_no_contact = 0;               // points at or past the zero-traction speed
};

// Every point of spec.web_speeds, the zero-traction and slip speeds, and for
// a grooved roller the plain one beside it.
TractionSweep run_traction_sweep(const TractionSpec& spec);

// The groove's gain: grooved over plain zero-traction speed; nullopt when the
// roller has no grooves, or the plain one has no clearance (no traction at all).
std::optional<double> groove_speed_gain(const TractionSweep& sweep);

}  // namespace coremodal
