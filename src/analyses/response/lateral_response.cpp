#include "analyses/response/lateral_response.hpp"

#include "analyses/response/modal_equations.hpp"

#include "beam/rotating_modes.hpp"
#include "common/error.hpp"
#include "effects/damping.hpp"
#include "eigensolve/tolerances.hpp"

#include <complex>

namespace coremodal {

using cd = std::complex<double>;

LateralResponse::LateralResponse(const BeamNetwork& network, double lambda_scale, double zeta)
    : network_(&network), lambda_scale_(lambda_scale) {
    const FamilySet lateral = lateral_family_set(network);
    if (!lateral) throw SolveError("the beam network has no bending DOF: no lateral response to compute");
    m_ = std::move(assemble_problems(network, {lateral}).front());
    G_ = assemble_gyroscopic(network, {m_}).front();
    DenseModes modes = dense_modes_at_rest(m_, lambda_scale);
    Phi_ = std::move(modes.Phi);
    lambda_ = std::move(modes.lambda);
    Ghat_ = Phi_.transpose() * (G_ * Phi_);
    set_damping({}, std::vector<std::optional<double>>(static_cast<size_t>(lambda_.size()), zeta));
}

void LateralResponse::set_damping(const RayleighDamping& rayleigh, const std::vector<std::optional<double>>& zeta) {
    modal_damping_ = modal_damping_coefficients(rayleigh, zeta, lambda_, kRigidEigenvalueFraction * lambda_scale_);
    Eigen::VectorXd own(lambda_.size());  // c_j less Rayleigh's part: what the matrix form adds in the modes
    for (Eigen::Index j = 0; j < lambda_.size(); ++j) own(j) = modal_damping_(j) - rayleigh.coefficient(lambda_(j));
    const Eigen::MatrixXd MPhi = m_.M * Phi_;
    D_ = MPhi * own.asDiagonal() * MPhi.transpose();
    if (rayleigh.alpha != 0) D_ += rayleigh.alpha * Eigen::MatrixXd(m_.M);
    if (rayleigh.beta != 0) D_ += rayleigh.beta * Eigen::MatrixXd(m_.K);
}

double LateralResponse::modal_damping_ratio(int j) const {
    return lambda_(j) < kRigidEigenvalueFraction * lambda_scale_ ? 0.0 : modal_damping_(j) / (2 * std::sqrt(lambda_(j)));
}

int LateralResponse::modes_below(double omega_cut) const {
    int n = 0;
    while (n < n_modes() && lambda_(n) <= omega_cut * omega_cut) ++n;
    return n;
}

double LateralResponse::mode_frequency_hz(int j) const { return std::sqrt(std::max(lambda_(j), 0.0)) / (2 * M_PI); }

Eigen::VectorXcd LateralResponse::to_rows(const Eigen::VectorXcd& network) const {
    Eigen::VectorXcd out(static_cast<Eigen::Index>(m_.free_dofs.size()));
    for (size_t r = 0; r < m_.free_dofs.size(); ++r) out(static_cast<Eigen::Index>(r)) = network(m_.free_dofs[r]);
    return out;
}

Eigen::VectorXcd LateralResponse::to_network(const Eigen::VectorXcd& rows) const {
    Eigen::VectorXcd out = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(network_->held.size()));
    for (size_t r = 0; r < m_.free_dofs.size(); ++r) out(m_.free_dofs[r]) = rows(static_cast<Eigen::Index>(r));
    return out;
}

Eigen::VectorXd LateralResponse::mode_shape(int j) const { return to_network(Phi_.col(j).cast<cd>()).real(); }

Eigen::VectorXd LateralResponse::mode_mass_shape(int j) const {
    const Eigen::VectorXd mass = m_.M * Phi_.col(j);
    return to_network(mass.cast<cd>()).real();
}

Eigen::VectorXcd LateralResponse::modal_coordinates(const Eigen::VectorXcd& f, double omega_spin, double omega,
                                                    int n) const {
    COREMODAL_ASSERT(n >= 1 && n <= n_modes());
    const Eigen::VectorXcd load = Phi_.leftCols(n).transpose().cast<cd>() * f;
    return solve_modal_equations(cd(0, omega * omega_spin) * Ghat_.topLeftCorner(n, n).cast<cd>(), lambda_,
                                 modal_damping_, omega, load);
}

Eigen::VectorXcd LateralResponse::superpose(const Eigen::VectorXcd& f, double omega_spin, double omega, int n,
                                            bool static_correction) const {
    Eigen::VectorXcd x = Phi_.leftCols(n).cast<cd>() * modal_coordinates(f, omega_spin, omega, n);
    if (static_correction && n < n_modes()) {
        const Eigen::Index rest = n_modes() - n;
        const Eigen::MatrixXd& Phi_r = Phi_.rightCols(rest);
        const Eigen::VectorXcd load = Phi_r.transpose().cast<cd>() * f;
        x += Phi_r.cast<cd>() * (load.array() / lambda_.tail(rest).array().cast<cd>()).matrix();
    }
    return x;
}

Eigen::VectorXcd LateralResponse::direct(const Eigen::VectorXcd& f, double omega_spin, double omega) const {
    const Eigen::MatrixXd K(m_.K), M(m_.M), G(G_);
    const Eigen::MatrixXcd A = (K - omega * omega * M).cast<cd>() + cd(0, omega) * (omega_spin * G + D_).cast<cd>();
    return A.partialPivLu().solve(f);
}

Eigen::VectorXd LateralResponse::static_response(const Eigen::VectorXd& f) const {
    const Eigen::VectorXd load = Phi_.transpose() * f;
    return Phi_ * (load.array() / lambda_.array()).matrix();
}

}  // namespace coremodal
