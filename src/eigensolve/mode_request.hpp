// What a case's [analysis] asks of any eigensolver (SLEPc for the solid and
// harmonic levels, Eigen for the beam network): the lowest modes or a band,
// the scale of the first elastic eigenvalue, the residual wanted. Free of
// PETSc; each solver's request adds its own settings to it.
#pragma once

#include <optional>

namespace coremodal {

struct ModeRequest {
    int n_modes = 20;                   // lowest modes wanted (if no band); pairs are never cut
    std::optional<double> lambda_min;   // band request, rad^2/s^2 (both set, or neither)
    std::optional<double> lambda_max;
    // Typical eigenvalue of the first elastic mode (closed-form estimates,
    // beam/eigenvalue_scale.hpp), rad^2/s^2. Sets the negative shift and the
    // scale below which a mode counts as rigid (eigensolve/tolerances.hpp).
    double lambda_scale = 1.0;
    double tolerance = 1e-10;  // relative residual ||K x - lambda M x|| / (||K|| ||x||)
};

}  // namespace coremodal
