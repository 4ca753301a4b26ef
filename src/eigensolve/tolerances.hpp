// The tolerances that say when two eigenvalues are one and when a mode is
// rigid: one definition each, shared by every solver (SLEPc for the solid and
// harmonic levels, Eigen for the beam network and the winder) and by the mode
// tools in modes/. Free of PETSc so that all of them can include it.
#pragma once

namespace coremodal {

// |lambda| below this fraction of the request's lambda_scale: a rigid-body
// mode. Rigid modes come out at |lambda| ~ 1e-9 of the first elastic
// eigenvalue or less (round-off of the shift, which is of the scale's order).
// The scale is the smallest closed-form estimate of the first elastic
// eigenvalue over every family of modes (beam/eigenvalue_scale.hpp): above it
// or near it for every shape, never 1e6 times above it, so no elastic mode
// falls under the line (tests/verification/test_short_bodies.cpp).
constexpr double kRigidEigenvalueFraction = 1e-6;

// The quadratic (gyroscopic) solver's rigid line, as a share of the first
// elastic frequency sqrt(lambda_scale): a rigid mode is a double zero of the
// quadratic problem, which SLEPc's PEP computes to about the square root of
// the working precision, so rigid modes come out at omega up to ~1e-3 of the
// scale (1.1e-3 measured on a free spinning ring), where the symmetric
// solver gives ~1e-5. Modes below this line are rigid (or the slow
// precession of a free spinning body) and are reported at 0 Hz.
constexpr double kQuadraticRigidFrequencyFraction = 1e-2;

// Two eigenvalues closer than this share of max(|lambda|, lambda_scale) are
// one cluster: a solver reports degenerate partners together or not at all
// (modal_solver.cpp, network_modes.cpp). Exact pairs of a symmetric mesh or
// network split by ~1e-10; distinct modes of one family by ~1e-4 and more.
constexpr double kClusterTolerance = 1e-6;

// The two tolerances below also group modes into degenerate pairs, but on
// frequencies that come from different meshes or meshes without the roll's
// symmetry, so they are wider than kClusterTolerance on purpose; unifying
// them with it (or with each other) changes study tracks and converge labels
// (docs/architecture-decisions.md).
//
// Study tracking by MAC (modes/tracking.cpp): modes closer than this relative
// frequency gap are one degenerate group (exact pairs split by ~1e-10;
// distinct ovalling modes of one family by ~1e-4 and more, docs/how-to/studies.md).
constexpr double kDegenerateGap = 1e-5;
// Converge's tracking by label (modes/label_tracking.cpp): neighbours with
// the same label closer than this relative frequency gap are one mode. A pair
// split by a mesh that is not 45-degree symmetric (around a multiple of 4
// only) differs by ~1e-5 to 1e-4, still one mode; two distinct modes of one
// label are far apart.
constexpr double kDegenerateTolerance = 1e-3;

}  // namespace coremodal
