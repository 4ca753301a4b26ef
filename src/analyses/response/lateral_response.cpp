#include "analyses/response/lateral_response.hpp"

#include "beam/rotating_modes.hpp"
#include "common/error.hpp"
#include "effects/damping.hpp"
#include "eigensolve/tolerances.hpp"

#include <complex>

namespace coremodal {

using cd = std::complex<double>;

LateralResponse::LateralResponse(const BeamNetwork& network, double lambda_scale, double zeta)
    : network_(&network), zeta_(zeta) {
    const FamilySet lateral = lateral_family_set(network);
    if (!lateral) throw SolveError("the beam network has no bending DOF: no lateral response to compute");
    m_ = std::move(assemble_problems(network, {lateral}).front());
    G_ = assemble_gyroscopic(network, {m_}).front();
    DenseModes modes = dense_modes_at_rest(m_, lambda_scale);
    Phi_ = std::move(modes.Phi);
    lambda_ = std::move(modes.lambda);
    Ghat_ = Phi_.transpose() * (G_ * Phi_);
    // A rigid mode (lambda ~ 0) has no frequency to damp at.
    const double rigid = kRigidEigenvalueFraction * lambda_scale;
    modal_damping_.resize(lambda_.size());
    for (Eigen::Index j = 0; j < lambda_.size(); ++j)
        modal_damping_(j) = lambda_(j) < rigid ? 0.0 : ModalDamping::coefficient(zeta, std::sqrt(lambda_(j)));
    const Eigen::MatrixXd MPhi = m_.M * Phi_;
    D_ = MPhi * modal_damping_.asDiagonal() * MPhi.transpose();
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
    Eigen::MatrixXcd A = cd(0, omega * omega_spin) * Ghat_.topLeftCorner(n, n).cast<cd>();
    for (int j = 0; j < n; ++j) A(j, j) += lambda_(j) - omega * omega + cd(0, omega * modal_damping_(j));
    const Eigen::VectorXcd load = Phi_.leftCols(n).transpose().cast<cd>() * f;
    return A.partialPivLu().solve(load);
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
