// The steps of a shift-and-invert solve that the solver's two paths share
// (eigensolve/modal_solver.cpp: a negative shift and a separate count;
// eigensolve/predicted_edge.cpp: one LDL^T factor at a predicted band edge
// that is operator and count). Internal to eigensolve/.
#pragma once

#include "eigensolve/block_lanczos.hpp"
#include "eigensolve/modal_solver.hpp"

#include <slepceps.h>

#include <string>
#include <vector>

namespace coremodal::shift_invert {

// The shift sits this far below zero, in units of the first elastic
// eigenvalue: rigid-body modes (lambda = 0) then make K - sigma M definite
// instead of singular, and the wanted low modes stay well separated in the
// shift-and-invert spectrum 1 / (lambda - sigma).
constexpr double kShiftFraction = 0.5;

// Extra modes computed beyond those reported: they locate the gap where the
// inertia check is placed and catch a degenerate partner of the last mode.
constexpr int kMinExtraModes = 4;

// What one solve gave: every converged pair, ascending.
struct Attempt {
    std::vector<double> lambdas;
    std::vector<PetscVector> vectors;
    int n_converged = 0;
    // Block Lanczos's predicted start when it was dropped for a random one
    // (block_lanczos.hpp, predicted_start_passes), for the summary's
    // solver line; empty otherwise.
    std::string start_dropped;
};

// Krylov-Schur on the symmetric-definite pencil (K, M), aimed at sigma.
PetscHandle<EPS, EPSDestroy> krylov_schur_at(Mat K, Mat M, double sigma);

// Every converged pair of a solved EPS, in ascending order of eigenvalue.
Attempt converged_pairs(EPS eps, Mat K);

// |lambda| below this is a rigid-body mode (tolerances.hpp).
double rigid_line(const SolveRequest& r);

// Whether block Lanczos (block_lanczos.hpp) solves for `wanted` pairs of
// this model rather than SLEPc's Krylov-Schur. `small_too`: on a model below
// kBlockLanczosMinDofs as well (a retry that needs blocks, modal_solver.cpp).
bool block_lanczos_applies(PetscInt n_dofs, int wanted, bool small_too = false);

// Block Lanczos on the factor F of K - sigma M for `wanted` pairs (the
// lowest; with sigma inside the spectrum, those below it), the passes said
// through `progress`; the pairs come lambda-ascending.
Attempt block_lanczos_attempt(Mat F, Mat M, double sigma, int wanted, const SolveRequest& request,
                              const Progress& progress);
// The same on an operator given as a function (block_lanczos.hpp: BlockSolve).
Attempt block_lanczos_attempt(const BlockSolve& solve, Mat M, double sigma, int wanted, const SolveRequest& request,
                              const Progress& progress);

// Says through `progress` when the factor F lives on disk (MUMPS out of
// core, petsc_algebra.hpp), which makes every pass over it slower.
void say_if_out_of_core(Mat F, const Progress& progress);

// The first n_report modes of a proven-complete attempt, M-normalised, with
// their residuals and the verification.
SolvedModes verified_modes(Mat K, Mat M, Attempt& a, int n_report, double check, long pivots, long found_below);

std::string unconverged_text(int n_converged, int wanted, const SolveRequest& request);

}  // namespace coremodal::shift_invert
