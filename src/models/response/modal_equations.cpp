#include "models/response/modal_equations.hpp"

#include "common/error.hpp"

#include <cmath>
#include <complex>

namespace coremodal {

using cd = std::complex<double>;

Eigen::VectorXcd solve_modal_equations(Eigen::MatrixXcd gyro_n, const Eigen::VectorXd& lambda,
                                       const Eigen::VectorXd& c, double omega, const Eigen::VectorXcd& load) {
    const Eigen::Index n = gyro_n.rows();
    COREMODAL_ASSERT(n == load.size() && n <= lambda.size() && n <= c.size());
    for (Eigen::Index j = 0; j < n; ++j) gyro_n(j, j) += lambda(j) - omega * omega + cd(0, omega * c(j));
    return gyro_n.partialPivLu().solve(load);
}

Eigen::VectorXd modal_damping_coefficients(const RayleighDamping& rayleigh,
                                           const std::vector<std::optional<double>>& zeta,
                                           const Eigen::VectorXd& lambda, double rigid_line) {
    COREMODAL_ASSERT(static_cast<Eigen::Index>(zeta.size()) == lambda.size());
    Eigen::VectorXd c(lambda.size());
    for (Eigen::Index j = 0; j < lambda.size(); ++j) {
        const std::optional<double>& z = zeta[static_cast<size_t>(j)];
        c(j) = !z ? rayleigh.coefficient(lambda(j))
                  : lambda(j) < rigid_line ? 0.0 : ModalDamping::coefficient(*z, std::sqrt(lambda(j)));
    }
    return c;
}

ModalDampingSplit split_modal_damping(const RayleighDamping& rayleigh, const std::vector<std::optional<double>>& zeta,
                                      const Eigen::VectorXd& lambda, double rigid_line) {
    ModalDampingSplit out{modal_damping_coefficients(rayleigh, zeta, lambda, rigid_line), Eigen::VectorXd(lambda.size())};
    for (Eigen::Index j = 0; j < lambda.size(); ++j) out.own(j) = out.total(j) - rayleigh.coefficient(lambda(j));
    return out;
}

Eigen::MatrixXcd imaginary_stiffness_term(const Eigen::MatrixXd& H_hat, int n) {
    if (H_hat.size() == 0) return Eigen::MatrixXcd::Zero(n, n);  // no imaginary stiffness
    return cd(0, 1) * H_hat.topLeftCorner(n, n).cast<cd>();
}

}  // namespace coremodal
