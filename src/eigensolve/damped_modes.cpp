#include "eigensolve/damped_modes.hpp"

#include "common/error.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

using cd = std::complex<double>;
using Dense = Eigen::MatrixXcd;

// A term, or zero when the model has none.
Dense term_or_zero(const Eigen::MatrixXd& A, Eigen::Index m) {
    if (A.size() == 0) return Dense::Zero(m, m);
    COREMODAL_ASSERT(A.rows() == m && A.cols() == m);
    return A.cast<cd>();
}

// The first companion form of lambda^2 M + lambda A1 + A0 with M^-1 applied:
// z = (x, lambda x), [[0, I], [-M^-1 A0, -M^-1 A1]] z = lambda z.
Dense companion(const Eigen::LLT<Eigen::MatrixXd>& M, const Dense& A0, const Dense& A1) {
    const Eigen::Index m = A0.rows();
    Dense C = Dense::Zero(2 * m, 2 * m);
    C.topRightCorner(m, m).setIdentity();
    // M^-1 of a complex matrix: the real factor on the real and imaginary parts.
    const auto solve = [&](const Dense& A) {
        Dense out(m, m);
        out.real() = M.solve(Eigen::MatrixXd(A.real()));
        out.imag() = M.solve(Eigen::MatrixXd(A.imag()));
        return out;
    };
    C.bottomLeftCorner(m, m) = -solve(A0);
    C.bottomRightCorner(m, m) = -solve(A1);
    return C;
}

}  // namespace

DampedModes damped_modes(const ProjectedDampedModel& model, double spin, double frequency_floor) {
    const Eigen::Index m = model.K.rows();
    COREMODAL_ASSERT(model.K.cols() == m && model.M.rows() == m && model.M.cols() == m);
    const Eigen::LLT<Eigen::MatrixXd> M(0.5 * (model.M + model.M.transpose()));
    if (M.info() != Eigen::Success) throw SolveError("the projected mass is not positive definite: no damped modes");
    const Dense A0 = model.K.cast<cd>() + cd(0, 1) * term_or_zero(model.H, m);
    const Dense A1 = term_or_zero(model.D, m) + spin * term_or_zero(model.G, m);
    const Eigen::ComplexEigenSolver<Dense> eig(companion(M, A0, A1));
    if (eig.info() != Eigen::Success) throw SolveError("the damped projected eigenproblem did not converge");
    const double norm0 = A0.norm(), norm1 = A1.norm(), norm2 = model.M.norm();
    DampedModes out;
    for (Eigen::Index k = 0; k < 2 * m; ++k) {
        const cd lambda = eig.eigenvalues()(k);
        if (lambda.imag() < -frequency_floor) continue;  // a partner of negative frequency
        if (lambda.imag() <= frequency_floor) {
            ++out.n_non_oscillating;
            continue;
        }
        DampedMode mode;
        mode.eigenvalue = lambda;
        const double omega = std::abs(lambda);
        mode.natural_frequency_hz = omega / (2 * M_PI);
        mode.damped_frequency_hz = lambda.imag() / (2 * M_PI);
        mode.zeta = -lambda.real() / omega;
        mode.shape = eig.eigenvectors().col(k).head(m).normalized();
        const Eigen::VectorXcd residual =
            (lambda * lambda) * (model.M.cast<cd>() * mode.shape) + lambda * (A1 * mode.shape) + A0 * mode.shape;
        mode.backward_error = residual.norm() / (norm0 + omega * norm1 + omega * omega * norm2);
        out.modes.push_back(std::move(mode));
    }
    std::sort(out.modes.begin(), out.modes.end(),
              [](const DampedMode& a, const DampedMode& b) { return a.damped_frequency_hz < b.damped_frequency_hz; });
    return out;
}

}  // namespace coremodal
