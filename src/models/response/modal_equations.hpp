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
// harmonic level's n = 1, modal_response.hpp), plus i Phi_n^T H Phi_n of an
// imaginary stiffness H (Term::imaginary_stiffness, effects/damping.hpp).
// Gh and Hh are kept dense: the whirl's coupling of the modes (and an H that
// is not proportional to K) is not diagonalised away.
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

// The viscous damping of a basis in the one split both matrix forms use
// (LateralResponse's dense D, ModalResponse's sparse alpha M + beta K plus
// Woodbury): c_j as above, and `own`, c_j less Rayleigh's alpha + beta
// lambda_j, the modes' low-rank part M Phi diag(own) Phi^T M.
struct ModalDampingSplit {
    Eigen::VectorXd total, own;
};
ModalDampingSplit split_modal_damping(const RayleighDamping& rayleigh, const std::vector<std::optional<double>>& zeta,
                                      const Eigen::VectorXd& lambda, double rigid_line);

// A term's operator A on the DOFs (stiffness, gyroscopic G, structural
// damping H) projected on modes Phi (M-orthonormal columns): Phi^T A Phi,
// dense. The one projection of a term on a modal basis, at every level.
template <class Operator>
Eigen::MatrixXd project_on_modes(const Operator& A, const Eigen::MatrixXd& Phi) {
    return Phi.transpose() * (A * Phi);
}

// The modal equations' term of an imaginary stiffness H (effects/damping.hpp):
// i Phi_n^T H Phi_n, added to gyro_n (dense: an H not proportional to K
// couples the modes, as G does).
Eigen::MatrixXcd imaginary_stiffness_term(const Eigen::MatrixXd& H_hat, int n);

}  // namespace coremodal
