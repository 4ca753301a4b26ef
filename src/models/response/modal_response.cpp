#include "models/response/modal_response.hpp"

#include "models/response/modal_equations.hpp"
#include "common/blas_threads.hpp"
#include "common/error.hpp"
#include "eigensolve/tolerances.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include <cmath>
#include <complex>

namespace coremodal {

using cd = std::complex<double>;
using ComplexSparse = Eigen::SparseMatrix<cd>;

struct ModalResponse::StiffnessFactor {
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> llt;
};

struct ModalResponse::ComplexStiffnessFactor {
    ComplexSparse K_iH;  // kept: UMFPACK's solve reads the matrix it factored
    Eigen::UmfPackLU<ComplexSparse> lu;
};

ModalResponse::ModalResponse(Eigen::SparseMatrix<double> K, Eigen::SparseMatrix<double> M,
                             Eigen::SparseMatrix<double> G, std::complex<double> gyroscopic_unit, ModalBasis basis,
                             double lambda_scale)
    : K_(std::move(K)), M_(std::move(M)), G_(std::move(G)), gyroscopic_unit_(gyroscopic_unit),
      basis_(std::move(basis)), lambda_scale_(lambda_scale) {
    COREMODAL_ASSERT(basis_.Phi.rows() == K_.rows() && basis_.Phi.cols() == basis_.lambda.size());
    auto factor = std::make_shared<StiffnessFactor>();
    factor->llt.compute(K_);
    K_factor_ = factor;
    if (factor->llt.info() != Eigen::Success)  // not positive definite
        throw SolveError("the stiffness of the roll in its stand is singular (a free body, or a free DOF without "
                         "stiffness): a spinning roll free to move has no steady forced response");
    Ghat_ = project_on_modes(G_, basis_.Phi);
    MPhi_ = M_ * basis_.Phi;
    set_damping({}, std::vector<std::optional<double>>(static_cast<size_t>(n_modes())));
}

void ModalResponse::set_damping(const RayleighDamping& rayleigh, const std::vector<std::optional<double>>& zeta) {
    rayleigh_ = rayleigh;
    ModalDampingSplit split = split_modal_damping(rayleigh, zeta, basis_.lambda, kRigidEigenvalueFraction * lambda_scale_);
    damping_ = std::move(split.total);
    own_damping_ = std::move(split.own);
}

void ModalResponse::set_imaginary_stiffness(Eigen::SparseMatrix<double> H) {
    COREMODAL_ASSERT(H.rows() == K_.rows() && H.cols() == K_.cols());
    H_ = std::move(H);
    Hhat_ = project_on_modes(H_, basis_.Phi);
    auto factor = std::make_shared<ComplexStiffnessFactor>();
    {
        const SingleThreadBlas one_thread;
        factor->K_iH = K_.cast<cd>() + cd(0, 1) * H_.cast<cd>();
        factor->lu.compute(factor->K_iH);
    }
    if (factor->lu.info() != Eigen::Success)  // K is positive definite and H = sum eta_p K_p >= 0: not expected
        throw SolveError("the complex stiffness K + i H (the damping's imaginary stiffness) could not be factored");
    KH_factor_ = factor;
}

int ModalResponse::modes_below(double omega_cut) const {
    int n = 0;
    while (n < n_modes() && basis_.lambda(n) <= omega_cut * omega_cut) ++n;
    return n;
}

double ModalResponse::mode_frequency_hz(int j) const {
    return std::sqrt(std::max(basis_.lambda(j), 0.0)) / (2 * M_PI);
}

Eigen::VectorXcd ModalResponse::modal_coordinates(const Eigen::VectorXcd& p, double omega_spin, double omega,
                                                  int n) const {
    COREMODAL_ASSERT(n >= 1 && n <= n_modes());
    const Eigen::VectorXcd load = basis_.Phi.leftCols(n).transpose().cast<cd>() * p;
    return solve_modal_equations((gyroscopic_unit_ * (omega * omega_spin)) * Ghat_.topLeftCorner(n, n).cast<cd>() +
                                     imaginary_stiffness_term(Hhat_, n),
                                 basis_.lambda, damping_, omega, load);
}

Eigen::VectorXcd ModalResponse::superpose(const Eigen::VectorXcd& p, double omega_spin, double omega, int n,
                                          bool static_correction) const {
    if (static_correction) return superpose(p, omega_spin, omega, n, complex_static_response(p));
    return basis_.Phi.leftCols(n).cast<cd>() * modal_coordinates(p, omega_spin, omega, n);
}

Eigen::VectorXcd ModalResponse::superpose(const Eigen::VectorXcd& p, double omega_spin, double omega, int n,
                                          const Eigen::VectorXcd& static_p) const {
    // K^-1 p less the kept modes' static part: what every other mode does far below its frequency.
    // With an imaginary stiffness both static parts carry it: static_p is (K + i H)^-1 p and the
    // kept modes' is (Lambda_n + i Hh_n)^-1 Phi_n^T p (exact when H = eta K).
    const auto Phi_n = basis_.Phi.leftCols(n);
    const Eigen::VectorXcd kept = Phi_n.transpose().cast<cd>() * p;
    Eigen::VectorXcd kept_static;
    if (Hhat_.size() == 0) {
        kept_static = (kept.array() / basis_.lambda.head(n).array().cast<cd>()).matrix();
    } else {
        Eigen::MatrixXcd A = imaginary_stiffness_term(Hhat_, n);
        A.diagonal() += basis_.lambda.head(n).cast<cd>();
        kept_static = A.partialPivLu().solve(kept);
    }
    const Eigen::VectorXcd eta = modal_coordinates(p, omega_spin, omega, n) - kept_static;
    return Phi_n.cast<cd>() * eta + static_p;
}

Eigen::VectorXd ModalResponse::static_response(const Eigen::VectorXd& p) const {
    const SingleThreadBlas one_thread;  // triangular solves: level-2 BLAS (common/blas_threads.hpp: why)
    return K_factor_->llt.solve(p);
}

Eigen::VectorXcd ModalResponse::complex_static_response(const Eigen::VectorXcd& p) const {
    if (KH_factor_) {
        const SingleThreadBlas one_thread;
        return KH_factor_->lu.solve(p);
    }
    return static_response(Eigen::VectorXd(p.real())).cast<cd>() + cd(0, 1) * static_response(Eigen::VectorXd(p.imag())).cast<cd>();
}

std::vector<ModalResponse::SynchronousCrossing> ModalResponse::synchronous_crossings(int order, int direction,
                                                                                  double omega_spin_max) const {
    COREMODAL_ASSERT(gyroscopic_unit_ == kOnePlane && (direction == 1 || direction == -1) && order >= 1);
    // A rigid mode (lambda ~ 0) crosses at Omega = 0: no critical speed; its
    // row would divide by zero.
    const double rigid_line = kRigidEigenvalueFraction * lambda_scale_;
    std::vector<Eigen::Index> elastic;
    for (Eigen::Index j = 0; j < basis_.lambda.size(); ++j)
        if (basis_.lambda(j) > rigid_line) elastic.push_back(j);
    const Eigen::Index n = static_cast<Eigen::Index>(elastic.size());
    std::vector<SynchronousCrossing> out;
    if (n == 0) return out;
    Eigen::VectorXd scale(n);  // lambda^-1/2
    for (Eigen::Index a = 0; a < n; ++a) scale(a) = 1 / std::sqrt(basis_.lambda(elastic[a]));
    Eigen::MatrixXd C(n, n);
    for (Eigen::Index a = 0; a < n; ++a)
        for (Eigen::Index b = 0; b < n; ++b)
            C(a, b) = scale(a) * scale(b) *
                      ((a == b ? double(order * order) : 0.0) - direction * order * Ghat_(elastic[a], elastic[b]));
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (C + C.transpose()));
    for (Eigen::Index k = n; k-- > 0;) {  // the largest nu first: the lowest spin
        const double nu = eig.eigenvalues()(k);
        if (!(nu > 0)) break;
        const double spin = 1 / std::sqrt(nu);
        if (spin > omega_spin_max) break;
        Eigen::VectorXd y = Eigen::VectorXd::Zero(basis_.lambda.size());
        for (Eigen::Index a = 0; a < n; ++a) y(elastic[a]) = scale(a) * eig.eigenvectors()(a, k);
        out.push_back({spin, std::move(y)});
    }
    return out;
}

Eigen::VectorXcd ModalResponse::direct(const Eigen::VectorXcd& p, double omega_spin, double omega) const {
    // A0 = K - omega^2 M + g omega Omega G + i omega (alpha M + beta K) + i H, sparse;
    // the modes' own damping is the low-rank term i omega U diag(d) U^T,
    // U = M Phi, d = own_damping_: (A0 + U C U^T)^-1 p = y - Z (I + C U^T Z)^-1 C U^T y,
    // y = A0^-1 p, Z = A0^-1 U, C = i omega diag(d) (Woodbury).
    ComplexSparse A0 = (K_ - omega * omega * M_).cast<cd>() + (gyroscopic_unit_ * (omega * omega_spin)) * G_.cast<cd>() +
                       cd(0, omega) * (rayleigh_.alpha * M_ + rayleigh_.beta * K_).cast<cd>();
    if (H_.nonZeros() > 0) A0 += cd(0, 1) * H_.cast<cd>();  // the imaginary stiffness, frequency independent
    Eigen::UmfPackLU<ComplexSparse> lu;
    {
        const SingleThreadBlas one_thread;
        lu.compute(A0);
    }
    if (lu.info() != Eigen::Success)
        throw SolveError("the direct frequency-response solve failed: its matrix is singular at " +
                         std::to_string(omega / (2 * M_PI)) + " Hz (an undamped resonance)");
    const Eigen::VectorXcd y = lu.solve(p);
    if (n_modes() == 0) return y;
    const Eigen::MatrixXcd U = MPhi_.cast<cd>();
    const Eigen::MatrixXcd Z = lu.solve(U);
    const Eigen::VectorXcd c = cd(0, omega) * own_damping_.cast<cd>();
    Eigen::MatrixXcd S = c.asDiagonal() * (U.transpose() * Z);
    S.diagonal().array() += 1.0;
    const Eigen::VectorXcd correction = S.partialPivLu().solve(c.asDiagonal() * (U.transpose() * y));
    return y - Z * correction;
}

}  // namespace coremodal
