#include "winder/winder_modes.hpp"

#include "beam/network_modes.hpp"  // count_eigenvalues_below
#include "common/error.hpp"
#include "modes/verification_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace coremodal {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The solve's shift, sigma = -(2 pi kShiftHz)^2: below every mode (a roll
// whose nips carry no load would be free, lambda = 0), so K - sigma M is
// positive definite.
constexpr double kShiftHz = 1.0;
// Eigenvalues closer than this share are one cluster: the completeness shift
// never falls between two partners of a degenerate pair (the two drums'
// identical modes).
constexpr double kClusterShare = 1e-8;

// Every mode, by the inverted pencil M x = mu (K - sigma M) x, mu = 1/(lambda -
// sigma), equilibrated to a unit diagonal: steel drums and soft paper nips
// spread K over many decades, and inverted, the lowest modes are the largest
// mu and keep their relative accuracy (beam/network_modes.cpp does the same).
void dense_modes(const WinderModel& m, double sigma, Eigen::VectorXd& lambda, Eigen::MatrixXd& X) {
    const SparseMatrix A_sparse = m.K - sigma * m.M;
    const Eigen::VectorXd scale = A_sparse.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd A = scale.asDiagonal() * Eigen::MatrixXd(A_sparse) * scale.asDiagonal();
    const Eigen::MatrixXd M = scale.asDiagonal() * Eigen::MatrixXd(m.M) * scale.asDiagonal();
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(M, A);
    if (solver.info() != Eigen::Success)
        throw SolveError("winder model: the dense eigensolver failed on " + std::to_string(m.n_dofs()) + " DOFs");
    const Eigen::VectorXd mu = solver.eigenvalues().reverse();  // largest mu = lowest lambda first
    lambda = (sigma + mu.array().inverse()).matrix();
    // Vectors come A-normalised: x^T M x = mu.
    X = scale.asDiagonal() * solver.eigenvectors().rowwise().reverse() * mu.cwiseSqrt().cwiseInverse().asDiagonal();
}

// Sum over the DOFs of each body kind of x_i (A x)_i: the energy of each kind
// when A is block-diagonal by body (M; the bodies' own stiffness).
std::array<double, kBodyKinds> by_kind(const WinderModel& m, const Eigen::VectorXd& x, const Eigen::VectorXd& Ax) {
    std::array<double, kBodyKinds> e{};
    for (int i = 0; i < m.n_dofs(); ++i) e[static_cast<int>(m.bodies[m.body_of[i]].kind)] += x[i] * Ax[i];
    return e;
}

void name_and_damp(const WinderModel& m, const WinderDamping& damping, const SparseMatrix& K_bodies, WinderModes& out) {
    const int n = static_cast<int>(out.modes.size());
    const Eigen::MatrixXd MX = m.M * out.shapes, KX = K_bodies * out.shapes, NX = m.K_nips * out.shapes;
    for (int i = 0; i < n; ++i) {
        WinderMode& mode = out.modes[i];
        const Eigen::VectorXd x = out.shapes.col(i);
        const auto kinetic = by_kind(m, x, MX.col(i));
        const auto strain = by_kind(m, x, KX.col(i));
        const double total_kinetic = kinetic[0] + kinetic[1] + kinetic[2];
        for (int k = 0; k < kBodyKinds; ++k) mode.kinetic_share[k] = kinetic[k] / total_kinetic;
        mode.type = static_cast<BodyKind>(std::max_element(kinetic.begin(), kinetic.end()) - kinetic.begin());
        const double nips = x.dot(NX.col(i));
        const double total_strain = strain[0] + strain[1] + strain[2] + nips;
        // A roll's own bending (beam rolls) is paper: damped like the nips.
        const double dissipated = damping.drums * strain[static_cast<int>(BodyKind::drum)] +
                                  damping.rider * strain[static_cast<int>(BodyKind::rider)] +
                                  damping.nips * (nips + strain[static_cast<int>(BodyKind::roll)]);
        mode.damping_ratio = total_strain > 0 ? dissipated / total_strain : 0.0;
    }
}

// Residuals of the reported modes (stored in each), M-orthonormality, and
// the Sylvester count.
Verification verify(const WinderModel& m, WinderModes& out, double sigma_all) {
    Verification v;
    const int n = out.n_reported;
    const double norm_K = Eigen::MatrixXd(m.K).cwiseAbs().colwise().sum().maxCoeff();  // max column sum
    const Eigen::MatrixXd X = out.shapes.leftCols(n);
    const Eigen::MatrixXd MX = m.M * X;
    for (int i = 0; i < n; ++i) {
        const Eigen::VectorXd r = m.K * X.col(i) - out.modes[i].eigenvalue * MX.col(i);
        out.modes[i].relative_residual = r.norm() / (norm_K * X.col(i).norm());
        v.max_relative_residual = std::max(v.max_relative_residual, out.modes[i].relative_residual);
    }
    if (n > 0)
        v.max_orthonormality_error = (X.transpose() * MX - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff();
    // The shift of the count: halfway to the next mode (or beyond the last one).
    const int total = static_cast<int>(out.modes.size());
    const double last = n > 0 ? out.modes[n - 1].eigenvalue : sigma_all;
    v.check_shift = n < total ? 0.5 * (last + out.modes[n].eigenvalue) : last + std::abs(last) + 1.0;
    const auto count = count_eigenvalues_below(m.K, m.M, v.check_shift);
    v.negative_pivots_at_shift = count.value_or(-1);
    v.modes_below_shift = n;
    v.complete = count && *count == n;
    return v;
}

}  // namespace

WinderModes solve_winder_modes(const WinderModel& m, const WinderDamping& damping, double max_frequency_hz) {
    const double sigma = -std::pow(2 * M_PI * kShiftHz, 2);
    Eigen::VectorXd lambda;
    WinderModes out;
    dense_modes(m, sigma, lambda, out.shapes);
    const int total = static_cast<int>(lambda.size());
    out.modes.resize(total);
    for (int i = 0; i < total; ++i)
        out.modes[i].eigenvalue = lambda[i], out.modes[i].frequency_hz = eigenvalue_hz(lambda[i]);
    // Report up to max_frequency, never cutting a cluster of (near) equal eigenvalues.
    const double lambda_max = std::pow(2 * M_PI * max_frequency_hz, 2);
    int n = 0;
    while (n < total && (lambda[n] <= lambda_max ||
                         (n > 0 && lambda[n] - lambda[n - 1] <= kClusterShare * std::abs(lambda[n]))))
        ++n;
    out.n_reported = n;
    const SparseMatrix K_bodies = m.K - m.K_nips;
    name_and_damp(m, damping, K_bodies, out);
    out.verification = verify(m, out, sigma);
    if (!out.verification.complete)
        throw SolveError(
            "winder model: " + std::to_string(n) + " modes found below " +
            std::to_string(eigenvalue_hz(out.verification.check_shift)) + " Hz but the inertia of K - sigma M counts " +
            std::to_string(out.verification.negative_pivots_at_shift) + "; this is a bug, please report it");
    // Residuals: the winder file's stiffnesses are bounded at input
    // (winder_scene.cpp), so a residual that fails is a solve that failed.
    if (!(out.verification.max_relative_residual <= kMaxVerifiedResidual))
        throw SolveError("winder model: the largest relative residual of its modes is " +
                         std::to_string(out.verification.max_relative_residual) + ", not a finite number at most " +
                         std::to_string(kMaxVerifiedResidual) +
                         "; look in the winder file for a stiffness or mass far from the others");
    return out;
}

std::complex<double> receptance(const WinderModes& modes, int dof, double frequency_hz) {
    const double w = 2 * M_PI * frequency_hz;
    std::complex<double> h = 0;
    for (size_t i = 0; i < modes.modes.size(); ++i) {
        const WinderMode& m = modes.modes[i];
        const double wi = std::sqrt(std::max(m.eigenvalue, 0.0));
        const double x = modes.shapes(dof, static_cast<Eigen::Index>(i));
        h += x * x / std::complex<double>(m.eigenvalue - w * w, 2 * m.damping_ratio * wi * w);
    }
    return h;
}

int response_dof(const WinderModel& m, DrumSide drum, ResponseDirection direction) {
    const int node = m.drum_centre_node[drum == DrumSide::front ? 0 : 1];
    return m.reduced_dof(node, direction == ResponseDirection::vertical ? beam_dof::uy : beam_dof::ux);
}

std::vector<double> mode_signature(const WinderModel& m, const Eigen::VectorXd& shape) {
    const Eigen::VectorXd network = m.T * shape;
    std::vector<double> s;
    for (size_t r = 0; r < m.network_dofs.size(); ++r) {
        const int dof = m.network_dofs[r] % beam_dof::per_node;
        if (dof == beam_dof::ux || dof == beam_dof::uy) s.push_back(network[static_cast<Eigen::Index>(r)]);
    }
    return s;
}

}  // namespace coremodal
