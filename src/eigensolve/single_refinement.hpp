// The single-precision factor's Ritz pairs refined in double (issue 39).
//
// Block Lanczos runs on the single factor's solves refined only loosely
// (kPassBackwardError: the first solve and at most one correction), so that
// each pass costs about one pass over the double factor's bytes instead of
// three. Its operator is then (A + E)^-1 M with a small E, and its Ritz
// pairs are those of K + E, M to about ||E||. One Rayleigh-Ritz step in
// double cleans them: the pairs' span X and its image Y = A^-1 M X through a
// solve refined to a double-precision backward error (kRefinedBackwardError)
// span a space where every wanted mode's error left outside it shrank by
// |lambda - sigma| / |lambda_far - sigma| and the rest is resolved exactly
// by the projection with the double K and M (Rayleigh-Ritz: Parlett, The
// Symmetric Eigenvalue Problem, SIAM 1998, chapter 11; the inexact
// operator's error tolerated as in inexact Krylov methods: Simoncini and
// Szyld, SIAM J. Sci. Comput. 25 (2003) 454-477). The steps repeat while a
// pair's residual with the double K, M stays above kRitzResidual. One
// process (as the single factor). Internal to eigensolve/.
#pragma once

#include "common/petsc_handle.hpp"
#include "eigensolve/single_factor.hpp"

#include <petscmat.h>

#include <vector>

namespace coremodal {

// The backward error each Lanczos pass's solve is refined to (one
// correction, sometimes two, where 1e-13 takes two, sometimes three),
// unless -factor_single_pass_error says otherwise. Measured on case 03's
// coarse solid (bench/results/log.md, "Fewer passes"): 1e-9 gives 26
// Lanczos passes + 2 Rayleigh-Ritz steps = 32 passes over the factor
// against 39 at 1e-13, frequencies within 2.4e-12 of the double run;
// unrefined solves leave block Lanczos short of its 1e-10 (500 restarts),
// and a run at 1e-8 was still solving after 8 minutes (stopped, not
// measured).
inline constexpr double kPassBackwardError = 1e-9;

// The Rayleigh-Ritz steps stop when every pair's relative residual
// ||K x - lambda M x|| / (||K||_1 ||x||), the verification's measure, is
// below this (the double factor's modes have ~1e-12), or after
// kMostRitzSteps.
inline constexpr double kRitzResidual = 1e-11;
inline constexpr int kMostRitzSteps = 6;

// kPassBackwardError or -factor_single_pass_error (an expert's measuring
// option; InputError when not positive).
double pass_backward_error();

// Block Lanczos's tolerance on the single factor's passes: the request's,
// unless -factor_single_lanczos_tolerance loosens it (measured: with solves
// left unrefined, 4e-8, the passes reach 1e-6 but not 1e-10, and the
// Rayleigh-Ritz steps then converge too slowly; bench/results/log.md).
inline constexpr double kSingleLanczosTolerance = 1e-10;
double single_lanczos_tolerance();

// Block Lanczos on the single factor's refined solves gets this many thick
// restarts; then the pass falls back to the double factor and says so
// (RefinementStalled). The double factor's passes restart once or twice
// (case 03: 14 passes of 16 vectors in a basis of 7 blocks); on case 02's
// shipped mesh (101,760 unknowns) the single factor's did not converge in
// 7 minutes where the double takes 16.7 s (bench/results/log.md, issue 39,
// session 21): an operator that slow to converge is not worth its cheaper
// factor.
inline constexpr int kMaxSingleRestarts = 12;

// Refines the pairs (lambdas ascending, vectors M-orthonormal) in place;
// returns the Rayleigh-Ritz steps taken. The lowest lambdas.size() Ritz
// values of the space replace them, ascending.
int refine_pairs_in_double(SingleLdlt& F, Mat K, Mat M, std::vector<double>& lambdas,
                           std::vector<PetscVector>& vectors);

}  // namespace coremodal
