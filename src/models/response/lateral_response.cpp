#include "models/response/lateral_response.hpp"

#include "models/response/modal_equations.hpp"

#include "beam/network_modes.hpp"
#include "beam/rotating_modes.hpp"
#include "common/error.hpp"
#include "effects/damping.hpp"
#include "eigensolve/tolerances.hpp"

#include <complex>

namespace coremodal {

using cd = std::complex<double>;

namespace {

using KFactor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;

// K factored once for the static part of the modes left out; none where K
// is singular or not positive definite (rigid modes: a free rotor).
std::shared_ptr<const KFactor> positive_definite_factor(const Eigen::SparseMatrix<double>& K) {
    auto factor = std::make_shared<KFactor>(K);
    if (factor->info() != Eigen::Success || !(factor->vectorD().array() > 0).all()) return nullptr;
    return factor;
}

// K^-1 f for a complex f, by the real factor.
Eigen::VectorXcd solve_static(const KFactor& factor, const Eigen::VectorXcd& f) {
    const Eigen::VectorXd re = factor.solve(Eigen::VectorXd(f.real())), im = factor.solve(Eigen::VectorXd(f.imag()));
    Eigen::VectorXcd out(f.size());
    out.real() = re, out.imag() = im;
    return out;
}

// A real matrix times a complex vector, without a complex copy of the matrix
// (the sweep's thousand products).
template <class Matrix>
Eigen::VectorXcd times(const Matrix& A, const Eigen::VectorXcd& v) {
    Eigen::VectorXcd out(A.rows());
    out.real() = A * v.real();
    out.imag() = A * v.imag();
    return out;
}

// The share of a network vector's M-norm that lies on the lateral rows.
double lateral_share(const NetworkMatrices& m, const Eigen::VectorXd& shape) {
    Eigen::VectorXd rows(static_cast<Eigen::Index>(m.free_dofs.size()));
    for (size_t r = 0; r < m.free_dofs.size(); ++r) rows(static_cast<Eigen::Index>(r)) = shape(m.free_dofs[r]);
    return rows.dot(m.M * rows);
}

}  // namespace

LateralResponse::LateralResponse(const BeamNetwork& network, double lambda_scale, NetworkMatrices lateral)
    : network_(&network), lambda_scale_(lambda_scale), m_(std::move(lateral)) {
    G_ = assemble_gyroscopic(network, {m_}).front();
    K_factor_ = positive_definite_factor(m_.K);
}

namespace {
NetworkMatrices lateral_problem(const BeamNetwork& network) {
    const FamilySet lateral = lateral_family_set(network);
    if (!lateral) throw SolveError("the beam network has no bending DOF: no lateral response to compute");
    return std::move(assemble_problems(network, {lateral}).front());
}
}  // namespace

LateralResponse::LateralResponse(const BeamNetwork& network, double lambda_scale, double zeta)
    : LateralResponse(network, lambda_scale, lateral_problem(network)) {
    DenseModes modes = dense_modes_at_rest(m_, lambda_scale);
    Phi_ = std::move(modes.Phi);
    lambda_ = std::move(modes.lambda);
    project_gyroscopic();
    set_damping({}, std::vector<std::optional<double>>(static_cast<size_t>(lambda_.size()), zeta));
}

std::optional<LateralResponse> LateralResponse::truncated(const BeamNetwork& network, double lambda_scale,
                                                          double omega_cut, double tolerance) {
    LateralResponse out(network, lambda_scale, lateral_problem(network));
    if (!out.K_factor_) return std::nullopt;
    // Every mode of the network up to the cutoff (all families; the band
    // request is proven complete by the inertia count), then the lateral ones.
    NetworkSolveRequest request;
    request.lambda_min = -lambda_scale;
    request.lambda_max = omega_cut * omega_cut;
    request.lambda_scale = lambda_scale;
    request.tolerance = tolerance;
    const NetworkModes modes = solve_network_modes(network, request);
    if (!modes.verification.complete) return std::nullopt;
    std::vector<int> kept;
    for (size_t j = 0; j < modes.shapes.size(); ++j)
        if (lateral_share(out.m_, modes.shapes[j]) > 0.5) kept.push_back(static_cast<int>(j));
    if (kept.size() < 2) return std::nullopt;
    const Eigen::Index n = static_cast<Eigen::Index>(kept.size());
    out.Phi_.resize(out.m_.K.rows(), n);
    out.lambda_.resize(n);
    for (Eigen::Index c = 0; c < n; ++c) {
        const Eigen::VectorXd& shape = modes.shapes[static_cast<size_t>(kept[static_cast<size_t>(c)])];
        for (size_t r = 0; r < out.m_.free_dofs.size(); ++r)
            out.Phi_(static_cast<Eigen::Index>(r), c) = shape(out.m_.free_dofs[r]);
        out.lambda_(c) = modes.eigenvalues[static_cast<size_t>(kept[static_cast<size_t>(c)])];
    }
    out.complete_ = false;
    out.project_gyroscopic();
    out.set_damping({}, std::vector<std::optional<double>>(static_cast<size_t>(n), 0.0));
    return out;
}

void LateralResponse::project_gyroscopic() { Ghat_ = project_on_modes(G_, Phi_); }

void LateralResponse::set_damping(const RayleighDamping& rayleigh, const std::vector<std::optional<double>>& zeta) {
    const ModalDampingSplit split = split_modal_damping(rayleigh, zeta, lambda_, kRigidEigenvalueFraction * lambda_scale_);
    modal_damping_ = split.total;
    rayleigh_ = rayleigh;
    own_damping_ = split.own;
    if (!complete_) return;  // the sparse direct solve takes the low-rank part as it is (direct)
    const Eigen::MatrixXd MPhi = m_.M * Phi_;
    D_ = MPhi * split.own.asDiagonal() * MPhi.transpose();
    if (rayleigh.alpha != 0) D_ += rayleigh.alpha * Eigen::MatrixXd(m_.M);
    if (rayleigh.beta != 0) D_ += rayleigh.beta * Eigen::MatrixXd(m_.K);
}

void LateralResponse::set_imaginary_stiffness(Eigen::SparseMatrix<double> H) {
    COREMODAL_ASSERT(H.rows() == m_.K.rows() && H.cols() == m_.K.cols());
    H_ = std::move(H);
    Hhat_ = project_on_modes(H_, Phi_);
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
    const Eigen::VectorXcd load = times(Phi_.leftCols(n).transpose(), f);
    return solve_modal_equations(cd(0, omega * omega_spin) * Ghat_.topLeftCorner(n, n).cast<cd>() + imaginary_stiffness_term(Hhat_, n),
                                 lambda_, modal_damping_, omega, load);
}

Eigen::VectorXcd LateralResponse::superpose(const Eigen::VectorXcd& f, double omega_spin, double omega, int n,
                                            bool static_correction, const Eigen::VectorXcd* K_inverse_f) const {
    Eigen::VectorXcd x = times(Phi_.leftCols(n), modal_coordinates(f, omega_spin, omega, n));
    if (!static_correction || (complete_ && n == n_modes())) return x;
    // The static part of the modes left out: K^-1 f less the kept modes'
    // static part (one sparse solve), or without a factor (a free rotor,
    // complete basis) their own sum.
    if (K_factor_) {
        const Eigen::VectorXcd load = times(Phi_.leftCols(n).transpose(), f);
        return x + (K_inverse_f ? *K_inverse_f : solve_static(*K_factor_, f)) -
               times(Phi_.leftCols(n), (load.array() / lambda_.head(n).array().cast<cd>()).matrix());
    }
    COREMODAL_ASSERT(complete_);
    const Eigen::Index rest = n_modes() - n;
    const Eigen::MatrixXd& Phi_r = Phi_.rightCols(rest);
    const Eigen::VectorXcd load = Phi_r.transpose().cast<cd>() * f;
    x += Phi_r.cast<cd>() * (load.array() / lambda_.tail(rest).array().cast<cd>()).matrix();
    return x;
}

std::optional<Eigen::VectorXcd> LateralResponse::static_solve(const Eigen::VectorXcd& f) const {
    if (!K_factor_) return std::nullopt;
    return solve_static(*K_factor_, f);
}

Eigen::VectorXcd LateralResponse::direct(const Eigen::VectorXcd& f, double omega_spin, double omega) const {
    if (!complete_) return sparse_direct(f, omega_spin, omega);
    const Eigen::MatrixXd K(m_.K), M(m_.M), G(G_);
    Eigen::MatrixXcd A = (K - omega * omega * M).cast<cd>() + cd(0, omega) * (omega_spin * G + D_).cast<cd>();
    if (H_.size() > 0) A += cd(0, 1) * Eigen::MatrixXd(H_).cast<cd>();  // the imaginary stiffness
    return A.partialPivLu().solve(f);
}

// (A_s + U C U^T) x = f with A_s = K - omega^2 M + i omega (Omega G + alpha M
// + beta K) + i H sparse (LU) and U = M Phi_n, C = i omega diag(own c_j):
// x = y - Z (I + C U^T Z)^-1 C U^T y, y = A_s^-1 f, Z = A_s^-1 U (no C^-1:
// a mode with no own damping has c_j = 0).
Eigen::VectorXcd LateralResponse::sparse_direct(const Eigen::VectorXcd& f, double omega_spin, double omega) const {
    using SparseC = Eigen::SparseMatrix<cd>;
    const cd i_omega(0, omega);
    SparseC A = (m_.K - omega * omega * m_.M).cast<cd>() + i_omega * (omega_spin * G_).cast<cd>();
    if (rayleigh_.alpha != 0) A += i_omega * (rayleigh_.alpha * m_.M).cast<cd>();
    if (rayleigh_.beta != 0) A += i_omega * (rayleigh_.beta * m_.K).cast<cd>();
    if (H_.size() > 0) A += cd(0, 1) * H_.cast<cd>();
    A.makeCompressed();
    Eigen::SparseLU<SparseC> lu(A);
    if (lu.info() != Eigen::Success) throw SolveError("the direct solve of the lateral problem: the system is singular");
    const Eigen::VectorXcd y = lu.solve(f);
    const Eigen::MatrixXcd U = (m_.M * Phi_).cast<cd>();
    const Eigen::MatrixXcd Z = lu.solve(U);
    const Eigen::VectorXcd c = i_omega * own_damping_.cast<cd>();
    const Eigen::Index n = Phi_.cols();
    const Eigen::MatrixXcd small = Eigen::MatrixXcd::Identity(n, n) + c.asDiagonal() * (U.transpose() * Z);
    const Eigen::VectorXcd w = small.partialPivLu().solve(c.asDiagonal() * (U.transpose() * y));
    return y - Z * w;
}

Eigen::VectorXd LateralResponse::static_response(const Eigen::VectorXd& f) const {
    if (K_factor_) return K_factor_->solve(f);
    const Eigen::VectorXd load = Phi_.transpose() * f;
    return Phi_ * (load.array() / lambda_.array()).matrix();
}

}  // namespace coremodal
