// What counts as a rigid-body mode, shared by every solver (SLEPc for the
// solid model, Eigen for the beam model); free of PETSc so that both can use it.
#pragma once

namespace coremodal {

// |lambda| below this fraction of SolveRequest::lambda_scale: a rigid-body
// mode. Rigid modes come out at |lambda| ~ 1e-9 of the first elastic
// eigenvalue; the first elastic mode is never below ~1e-2 of a beam estimate.
constexpr double kRigidEigenvalueFraction = 1e-6;

}  // namespace coremodal
