#include "eigensolve/damped_modes.hpp"

#include "common/error.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

using cd = std::complex<double>;
using ComplexDense = Eigen::MatrixXcd;

// A term, or zero when the model has none.
ComplexDense term_or_zero(const Eigen::MatrixXd& A, Eigen::Index m) {
    if (A.size() == 0) return ComplexDense::Zero(m, m);
    COREMODAL_ASSERT(A.rows() == m && A.cols() == m);
    return A.cast<cd>();
}

// The first companion form of lambda^2 M + lambda A1 + A0 with M^-1 applied:
// z = (x, lambda x), [[0, I], [-M^-1 A0, -M^-1 A1]] z = lambda z.
ComplexDense companion(const Eigen::LLT<Eigen::MatrixXd>& M, const ComplexDense& A0, const ComplexDense& A1) {
    const Eigen::Index m = A0.rows();
    ComplexDense C = ComplexDense::Zero(2 * m, 2 * m);
    C.topRightCorner(m, m).setIdentity();
    // M^-1 of a complex matrix: the real factor on the real and imaginary parts.
    const auto solve = [&](const ComplexDense& A) {
        ComplexDense out(m, m);
        out.real() = M.solve(Eigen::MatrixXd(A.real()));
        out.imag() = M.solve(Eigen::MatrixXd(A.imag()));
        return out;
    };
    C.bottomLeftCorner(m, m) = -solve(A0);
    C.bottomRightCorner(m, m) = -solve(A1);
    return C;
}

// Eigenvalues this close (relative) are one multiple eigenvalue: mirrored
// families make every one at rest double, and the companion form's
// eigenvalues of a double one came out 3e-8 to 1.2e-7 apart (case 12's core
// at the harmonic level, damped, 2026-11-29).
constexpr double kSameEigenvalue = 1e-6;

// The norms of A0, A1 and M, for the backward error at |lambda| = omega.
struct TermNorms {
    double a0, a1, m;
    double at(double omega) const { return a0 + omega * a1 + omega * omega * m; }
};

// The vectors of a multiple eigenvalue as an orthonormal basis of its
// eigenspace. The Schur form's back-substitution divides by the difference
// of equal eigenvalues, and its vectors for a double one can come out nearly
// parallel: the damped partners of a bending pair at rest were then one
// vector twice, and one member of the pair matched no damped mode (with one
// BLAS thread, 2026-11-29). The right singular vectors of Q(lambda) =
// lambda^2 M + lambda A1 + A0 for its smallest singular values span the
// eigenspace of a semisimple eigenvalue; they are kept only where their
// backward error is as small as the Schur vectors' (a defective eigenvalue
// has no such basis).
void span_multiple_eigenvalues(const Eigen::MatrixXd& M, const ComplexDense& A0, const ComplexDense& A1,
                               const TermNorms& norms, std::vector<DampedMode>& modes) {
    for (size_t first = 0; first < modes.size();) {
        size_t end = first + 1;
        const cd lambda = modes[first].eigenvalue;
        while (end < modes.size() && std::abs(modes[end].eigenvalue - lambda) <= kSameEigenvalue * std::abs(lambda))
            ++end;
        const Eigen::Index c = static_cast<Eigen::Index>(end - first);
        if (c > 1) {
            const ComplexDense Q = (lambda * lambda) * M.cast<cd>() + lambda * A1 + A0;
            const double scale = norms.at(std::abs(lambda));
            const Eigen::BDCSVD<ComplexDense> svd(Q, Eigen::ComputeFullV);
            const ComplexDense V = svd.matrixV().rightCols(c);  // singular values descend
            double worst = 0, largest = 0;
            for (Eigen::Index j = 0; j < c; ++j) {
                worst = std::max(worst, (Q * V.col(j)).norm() / scale);
                largest = std::max(largest, modes[first + size_t(j)].backward_error);
            }
            if (worst <= std::max(largest, 1e-12))
                for (Eigen::Index j = 0; j < c; ++j) {
                    modes[first + size_t(j)].shape = V.col(j);
                    modes[first + size_t(j)].backward_error = (Q * V.col(j)).norm() / scale;
                }
        }
        first = end;
    }
}

}  // namespace

DampedModes damped_modes(const ProjectedDampedModel& model, double spin, double frequency_floor) {
    const Eigen::Index m = model.K.rows();
    COREMODAL_ASSERT(model.K.cols() == m && model.M.rows() == m && model.M.cols() == m);
    const Eigen::LLT<Eigen::MatrixXd> M(0.5 * (model.M + model.M.transpose()));
    if (M.info() != Eigen::Success) throw SolveError("the projected mass is not positive definite: no damped modes");
    const ComplexDense A0 = model.K.cast<cd>() + cd(0, 1) * term_or_zero(model.H, m);
    const ComplexDense A1 = term_or_zero(model.D, m) + spin * term_or_zero(model.G, m);
    const Eigen::ComplexEigenSolver<ComplexDense> eig(companion(M, A0, A1));
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
        mode.backward_error = residual.norm() / TermNorms{norm0, norm1, norm2}.at(omega);
        out.modes.push_back(std::move(mode));
    }
    std::sort(out.modes.begin(), out.modes.end(),
              [](const DampedMode& a, const DampedMode& b) { return a.damped_frequency_hz < b.damped_frequency_hz; });
    span_multiple_eigenvalues(model.M, A0, A1, {norm0, norm1, norm2}, out.modes);
    return out;
}

}  // namespace coremodal
