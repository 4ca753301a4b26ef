// What counts as a rigid-body mode, shared by every solver (SLEPc for the
// solid model, Eigen for the beam model); free of PETSc so that both can use it.
#pragma once

namespace coremodal {

// |lambda| below this fraction of SolveRequest::lambda_scale: a rigid-body
// mode. Rigid modes come out at |lambda| ~ 1e-9 of the first elastic
// eigenvalue or less (round-off of the shift, which is of the scale's order).
// The scale is the smallest closed-form estimate of the first elastic
// eigenvalue over every family of modes (beam/eigenvalue_scale.hpp): above it
// or near it for every shape, never 1e6 times above it, so no elastic mode
// falls under the line (tests/verification/test_short_bodies.cpp).
constexpr double kRigidEigenvalueFraction = 1e-6;

}  // namespace coremodal
