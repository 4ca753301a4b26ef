// What the eigen solve proves about the modes it returns: the largest
// residual and orthonormality error, and the inertia count that shows no mode
// below the check shift was missed. Written by eigensolve/, carried by
// modes/ModeSet and the model levels, checked by modes/verification_check.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace coremodal {

// The frequency in Hz of an eigenvalue lambda = omega^2 (rad^2/s^2): a mode's
// or a check shift's; a rigid mode's round-off negative one gives 0.
inline double eigenvalue_hz(double lambda) { return std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI); }

// Which precision factored K - sigma M where the solid level's one factor at
// the predicted band edge gave the modes and their count (issue 39;
// docs/theory/methods.md, "A count from a single-precision factor"), and
// why: what the run's summary, console and report say. Absent on every
// other path (no fake value).
struct FactorPrecisionUsed {
    std::string used;   // "single" or "double"
    std::string asked;  // -factor_precision: "auto", "single" or "double"
    std::string why;
    std::string count;  // where the count came from, with the single factor's margin
};

struct Verification {
    double max_relative_residual = 0;
    double max_orthonormality_error = 0;  // max |X^T M X - I|
    double check_shift = 0;               // sigma of the inertia check, rad^2/s^2
    long negative_pivots_at_shift = 0;    // eigenvalues below check_shift by Sylvester
    long modes_below_shift = 0;           // modes accounted for below check_shift: found, or counted below a band
    // A band whose lower edge lies above the rigid modes: the eigenvalues below
    // that edge that were counted by inertia and not computed (an empty band
    // is proven by two counts, N(lower edge) = N(upper edge), without a solve).
    long eigenvalues_below_band = 0;
    bool complete = false;                // the two counts agree
    std::optional<FactorPrecisionUsed> factor_precision;

    long modes_found_below_shift() const { return modes_below_shift - eigenvalues_below_band; }
};

}  // namespace coremodal
