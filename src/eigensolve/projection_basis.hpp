// The building blocks of a projection basis from a set's PETSc operators
// (eigensolve/projected_gyroscopic): the modes at rest, their static
// responses to the spin's forces, M-orthonormalisation in dense algebra,
// and the small conversions between PETSc and Eigen it needs. One process
// (the projected sweep refuses mpirun).
#pragma once

#include "common/petsc_handle.hpp"
#include "eigensolve/modal_solver.hpp"

#include <Eigen/Dense>

#include <vector>

namespace coremodal {

// A V, column by column.
Eigen::MatrixXd apply_columns(Mat A, const Eigen::MatrixXd& V);

// The values of a sequential vector.
Eigen::VectorXd values_of(Vec x);

// The indices of an index set.
std::vector<PetscInt> indices_of(IS is);

// One pass of M-orthonormalisation: columns scaled to M-norm 1, then the
// eigenvectors of their Gram matrix, dependent directions dropped.
Eigen::MatrixXd m_orthonormal_pass(Mat M, const Eigen::MatrixXd& V);

// The lowest n_rest modes at rest of (K, M), verified and counted (solve_modes).
SolvedModes rest_modes(Mat K, Mat M, double model_mass, const SolveRequest& request, int n_rest);

// For every force matrix A and mode at rest x: u_1 = S^-1 A x and
// u_k = S^-1 M u_(k-1) up to kKrylovDepth terms, S = K + tau^2 M factored
// once (Cholesky). u_1 is the static response at -tau^2; the further terms
// are the series of the response at a frequency omega in powers of
// (omega^2 + tau^2), which a mode far above tau needs.
std::vector<Eigen::VectorXd> static_responses(Mat K, Mat M, double tau, const std::vector<Mat>& forces,
                                              const std::vector<PetscVector>& rest);

}  // namespace coremodal
