// The generalized Hermitian eigenproblem K x = lambda M x with SLEPc:
// Krylov–Schur, shift-and-invert on a factor of K - sigma M. Four acts
// (SLEPc ex13): configure, solve, extract and verify, prove complete. With a
// predicted band edge, one MUMPS LDL^T factor just above the wanted modes
// is both the operator and the completeness count; otherwise a Cholesky
// factor at a negative shift and a second (LDL^T) factor for the count.
#pragma once

#include "assembly/operator_set.hpp"
#include "common/petsc_handle.hpp"
#include "eigensolve/mode_request.hpp"
#include "eigensolve/tolerances.hpp"
#include "eigensolve/verification.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The case's request (mode_request.hpp) and SLEPc's iteration limit.
struct SolveRequest : ModeRequest {
    int max_iterations = 500;
    // The lowest eigenvalues of another model of the same scene (rad^2/s^2,
    // ascending; e.g. the harmonic level's for the solid's body of
    // revolution), or none. When it reaches past the wanted modes, K - sigma M
    // is factored once (LDL^T) in the predicted gap above them and that
    // factor serves both the shift-and-invert and the inertia count; a wrong
    // prediction falls back to a second count, or to the negative shift.
    std::vector<double> predicted_eigenvalues;
    // Vectors near the lowest modes (K's layout; e.g. the harmonic level's
    // modes at the solid mesh's nodes), or none: block Lanczos's first block
    // (block_lanczos.hpp). They change how fast the modes converge, never
    // which are accepted or the count. Shared: requests are copied.
    std::shared_ptr<const std::vector<PetscVector>> predicted_vectors;
};

// The most modes one eigenproblem is solved for ([analysis] modes has the
// same bound, scene/case_keys.cpp). The solver computes every mode below a
// band's upper edge; a band above more than this many is refused at once.
constexpr int kMaxModesPerProblem = 10000;

struct SolvedModes {
    std::vector<double> eigenvalues;  // ascending
    std::vector<PetscVector> vectors; // M-normalised
    std::vector<double> relative_residuals;
    Verification verification;
};

using Progress = std::function<void(const std::string&)>;

// Solves, verifies every pair, and proves by the inertia of K - sigma M that no
// mode below the highest reported one was missed (one automatic retry with a
// larger subspace; then SolveError). Degenerate partners of the last requested
// mode are always included, so a pair is never cut in half.
// A band is counted first: an empty one (as many eigenvalues below either
// edge) returns no modes, proven complete, without a solve; one whose upper
// edge lies above kMaxModesPerProblem eigenvalues, or above every eigenvalue
// of the model, throws InputError before any solve. Otherwise every mode
// below the upper edge is computed (the caller keeps those in_band).

// The operator set's problem type decides the method: while it holds only
// stiffness, geometric stiffness and mass, the symmetric generalized problem
// (K + K_sigma) x = lambda M x solved here. A gyroscopic or damping term
// makes it quadratic, which this function refuses (SolveError).
SolvedModes solve_modes(const OperatorSet& operators, const SolveRequest& request, const Progress& progress);

// Whether eigenvalue lambda belongs to the request: every one when there is
// no band; else lambda_min <= lambda <= lambda_max, a rigid-body mode
// (|lambda| below the rigid line, which round-off may make slightly
// negative) counting as lambda = 0.
bool in_band(double lambda, const SolveRequest& request);

// The package that factors K - sigma M for shift-and-invert on `comm`:
// CHOLMOD in one process (a smaller factor than Debian's MUMPS), MUMPS in
// parallel. The completeness count always uses MUMPS's LDL^T.
const char* shift_invert_factor_package(MPI_Comm comm);

// Number of eigenvalues of K x = lambda M x below sigma (Sylvester's law of
// inertia: negative pivots of the LDL^T factor of K - sigma M).
long count_eigenvalues_below(const OperatorSet& operators, double sigma);

}  // namespace coremodal
