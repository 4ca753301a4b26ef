// What the eigen solve proves about the modes it returns: the largest
// residual and orthonormality error, and the inertia count that shows no mode
// below the check shift was missed. Written by eigensolve/, carried by
// modes/ModeSet and the model levels, checked by modes/verification_check.
#pragma once

namespace coremodal {

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

    long modes_found_below_shift() const { return modes_below_shift - eigenvalues_below_band; }
};

}  // namespace coremodal
