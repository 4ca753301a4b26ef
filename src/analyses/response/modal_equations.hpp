// The modal equations of the forced response, the same at every model level
// (docs/theory/response.md, "The solver", step 3): with x = Phi_n eta in the n
// lowest modes at rest (M-orthonormal, eigenvalues lambda_j),
//
//     (Lambda_n - omega^2 I + i omega diag(c_n) + gyro_n) eta = Phi_n^T f
//
// where gyro_n is the gyroscopic term projected on those modes at this spin
// and load frequency: i omega Omega Gh_n for the beam network's two planes
// (G skew), omega Omega Gh_n for the complex plane u = u_x + i u_y of an
// axisymmetric model under a load turning forward (G symmetric; the
// harmonic level's n = 1, modal_response.hpp). Gh is kept dense: the
// whirl's coupling of the modes is not diagonalised away.
#pragma once

#include "effects/damping.hpp"

#include <Eigen/Dense>

#include <optional>
#include <vector>

namespace coremodal {

// eta for the load Phi_n^T f (`load`), lambda and c of the n modes.
Eigen::VectorXcd solve_modal_equations(Eigen::MatrixXcd gyro_n, const Eigen::VectorXd& lambda,
                                       const Eigen::VectorXd& c, double omega, const Eigen::VectorXcd& load);

// c_j = Phi_j^T D Phi_j of each mode (effects/damping.hpp): Rayleigh's
// alpha + beta lambda_j where zeta[j] is empty, 2 zeta_j omega_j where it is
// given, and 0 for a rigid mode (lambda_j below rigid_line: no frequency to
// damp at).
Eigen::VectorXd modal_damping_coefficients(const RayleighDamping& rayleigh,
                                           const std::vector<std::optional<double>>& zeta,
                                           const Eigen::VectorXd& lambda, double rigid_line);

}  // namespace coremodal
