// One factorization for the solve and the count (issue 19). Given a
// prediction of the lowest eigenvalues (another model of the same scene:
// SolveRequest::predicted_eigenvalues), K - sigma M is factored once, by
// MUMPS's LDL^T, at a shift sigma in the predicted gap above the wanted
// modes. That one factor is the shift-and-invert operator, and its negative
// pivots are the number of eigenvalues below sigma (Sylvester): when the
// solve finds exactly that many below sigma, nothing below was missed, with
// no second factorization. Internal to eigensolve/ (modal_solver.cpp).
#pragma once

#include "eigensolve/modal_solver.hpp"

#include <optional>

namespace coremodal::shift_invert {

// Halfway into the predicted gap after the wanted modes' cluster, or none
// (no prediction past them, a free body, a band).
std::optional<double> predicted_shift(const SolveRequest& r, int wanted);

// The wanted modes from the one factor at sigma, proven complete by its
// count: block Lanczos where it applies, else SLEPc's Krylov-Schur; none,
// said through `progress`, when the shift or the factor fails them (the
// caller then takes a negative shift and a separate count).
std::optional<SolvedModes> solve_at_predicted_edge(Mat K, Mat M, const SolveRequest& request, int wanted,
                                                   double sigma, long n_dofs, const Progress& progress);

}  // namespace coremodal::shift_invert
