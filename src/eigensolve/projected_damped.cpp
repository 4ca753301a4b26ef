#include "eigensolve/projected_damped.hpp"

#include "common/blas_threads.hpp"
#include "common/error.hpp"
#include "common/petsc_handle.hpp"
#include "eigensolve/gyroscopic_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "eigensolve/projection_basis.hpp"

#include <cmath>
#include <complex>
#include <vector>

namespace coremodal {
namespace {

using cd = std::complex<double>;

// A V, or empty for an absent term.
Eigen::MatrixXd applied_or_empty(Mat A, const Eigen::MatrixXd& V) {
    return A ? apply_columns(A, V) : Eigen::MatrixXd();
}
double norm_or_zero(Mat A) { return A ? norm_1(A) : 0.0; }
Mat term_or_null(const OperatorSet& ops, Term t) { return ops.has(t) ? ops[t] : nullptr; }

// (A V) y, or 0 for an absent term.
Eigen::VectorXcd times(const Eigen::MatrixXd& AV, const Eigen::VectorXcd& y, Eigen::Index n) {
    return AV.size() == 0 ? Eigen::VectorXcd::Zero(n) : Eigen::VectorXcd(AV.cast<cd>() * y);
}

}  // namespace

ProjectedDamped::ProjectedDamped(const OperatorSet& ops, const SolveRequest& request, int n_rest) {
    COREMODAL_ASSERT(mpi_size(PetscObjectComm((PetscObject)ops.K())) == 1 && !request.lambda_max);
    const EffectiveStiffness at_rest(ops, 0.0);  // K + K_sigma
    const Mat K0 = at_rest.get(), M = ops.M(), G = term_or_null(ops, Term::gyroscopic),
              D = term_or_null(ops, Term::damping), K_omega = term_or_null(ops, Term::centrifugal),
              H = term_or_null(ops, Term::imaginary_stiffness);
    rigid_omega_ = gyroscopic_rigid_omega(request);

    // 1. The modes at rest and their static responses to every other force.
    const SolvedModes rest = rest_modes(K0, M, ops.model_mass, request, n_rest);
    std::vector<Mat> forces;
    for (Mat A : {G, D, H, K_omega})
        if (A) forces.push_back(A);
    // The static responses' shift, as the undamped branch's: S = K + tau^2 M positive definite.
    const double tau = kTargetFraction * std::sqrt(request.lambda_scale);
    const std::vector<Eigen::VectorXd> enrichment = static_responses(K0, M, tau, forces, rest.vectors);

    // 2. The basis, M-orthonormal (twice, as the undamped branch's).
    PetscInt n_dofs;
    COREMODAL_PETSC(MatGetSize(K0, &n_dofs, nullptr));
    Eigen::MatrixXd V(n_dofs, static_cast<Eigen::Index>(rest.vectors.size() + enrichment.size()));
    Eigen::Index col = 0;
    for (const PetscVector& x : rest.vectors) V.col(col++) = values_of(x);
    for (const Eigen::VectorXd& x : enrichment) V.col(col++) = x;
    V_ = m_orthonormal_pass(M, m_orthonormal_pass(M, V));

    // 3. Every term applied to V once (the residuals) and projected.
    const SingleThreadBlas one_thread;
    applied_ = {apply_columns(K0, V_),   applied_or_empty(K_omega, V_), apply_columns(M, V_),
                applied_or_empty(G, V_), applied_or_empty(D, V_),       applied_or_empty(H, V_)};
    const auto project = [&](const Eigen::MatrixXd& AV) {
        return AV.size() == 0 ? Eigen::MatrixXd() : Eigen::MatrixXd(V_.transpose() * AV);
    };
    projected_ = {project(applied_.K), project(applied_.M), project(applied_.G), project(applied_.D),
                  project(applied_.H)};
    K_omega_ = project(applied_.K_omega);
    norm_K_ = norm_1(K0), norm_K_omega_ = norm_or_zero(K_omega), norm_M_ = norm_1(M);
    norm_G_ = norm_or_zero(G), norm_D_ = norm_or_zero(D), norm_H_ = norm_or_zero(H);
}

double ProjectedDamped::full_residual(const DampedMode& mode, double spin) const {
    const Eigen::Index n = V_.rows();
    const cd lambda = mode.eigenvalue;
    const Eigen::VectorXcd& y = mode.shape;
    const Eigen::VectorXcd stiffness =
        times(applied_.K, y, n) + (spin * spin) * times(applied_.K_omega, y, n) + cd(0, 1) * times(applied_.H, y, n);
    const Eigen::VectorXcd r = (lambda * lambda) * times(applied_.M, y, n) +
                               lambda * (times(applied_.D, y, n) + spin * times(applied_.G, y, n)) + stiffness;
    const double w = std::abs(lambda);
    const double scale =
        norm_K_ + spin * spin * norm_K_omega_ + norm_H_ + w * (norm_D_ + spin * norm_G_) + w * w * norm_M_;
    return r.norm() / (scale * (V_.cast<cd>() * y).norm());
}

DampedModes ProjectedDamped::modes_at(double spin) const {
    const SingleThreadBlas one_thread;  // small dense problems (common/blas_threads.hpp)
    ProjectedDampedModel model = projected_;
    if (K_omega_.size() > 0) model.K += spin * spin * K_omega_;
    DampedModes out = damped_modes(model, spin, rigid_omega_);
    for (DampedMode& mode : out.modes) mode.backward_error = full_residual(mode, spin);
    return out;
}

}  // namespace coremodal
