// The projected quadratic solver's damped branch against closed forms: a
// spinning chain of point masses in two planes, fixed at both ends, with
// Rayleigh damping D = alpha M + beta K and a uniform loss factor H = eta K.
// K = k T (x) I_2 (T the chain's tridiag(-1, 2, -1)), M = m I, G = g I_N (x) J,
// J = [[0, -1], [1, 0]]: the chain's modes at rest, omega_j^2 = (4 k / m)
// sin^2(j pi / (2 (N + 1))), diagonalise every term, and J's eigenvectors
// (1, -+i) (J v = +-i v) split each into the two whirls,
//     m lambda^2 + (c_j +- i Omega g) lambda + m omega_j^2 (1 + i eta) = 0,
// c_j = m (alpha + beta omega_j^2): the root of positive frequency of each.
#include "eigensolve/projected_damped.hpp"

#include "eigensolve/projected_gyroscopic.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

using namespace coremodal;

namespace {

using cd = std::complex<double>;

// Every matrix on one sparsity pattern (`pattern`'s non-zeros, zeros stored),
// as the assembly makes them: the solver's K - sigma M relies on it.
PetscMatrix petsc_matrix(const Eigen::MatrixXd& A, const Eigen::MatrixXd& pattern) {
    PetscMatrix m;
    const PetscInt n = A.rows();
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 6, nullptr, m.out()));
    for (PetscInt i = 0; i < n; ++i)
        for (PetscInt j = 0; j < n; ++j)
            if (pattern(i, j) != 0.0) COREMODAL_PETSC(MatSetValue(m, i, j, A(i, j), INSERT_VALUES));
    COREMODAL_PETSC(MatAssemblyBegin(m, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(m, MAT_FINAL_ASSEMBLY));
    return m;
}

struct Chain {
    int n = 20;
    double m = 0.5, k = 2e4, g = 0.3, alpha = 0.5, beta = 2e-5, eta = 0.02;
    // Mass i's x (p = 0) or y (p = 1): the planes one after the other.
    int dof(int i, int p) const { return p * n + i; }
    double omega(int j) const { return 2 * std::sqrt(k / m) * std::sin(j * M_PI / (2 * (n + 1))); }
    // The whirls of chain modes 1..j_max at spin Omega: positive frequency, ascending.
    std::vector<cd> whirls(int j_max, double spin, bool viscous, bool structural) const {
        std::vector<cd> out;
        for (int j = 1; j <= j_max; ++j) {
            const double w2 = omega(j) * omega(j), c = viscous ? m * (alpha + beta * w2) : 0.0;
            const cd k_j = m * w2 * cd(1, structural ? eta : 0.0);
            for (const double s : {1.0, -1.0}) {
                const cd b(c, s * spin * g), root = std::sqrt(b * b - 4.0 * m * k_j);
                for (const cd r : {(-b + root) / (2 * m), (-b - root) / (2 * m)})
                    if (r.imag() > 0) out.push_back(r);
            }
        }
        std::sort(out.begin(), out.end(), [](cd a, cd b) { return a.imag() < b.imag(); });
        return out;
    }
    Eigen::MatrixXd stiffness() const {
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
        for (int i = 0; i < n; ++i)
            for (int p = 0; p < 2; ++p) {
                K(dof(i, p), dof(i, p)) = 2 * k;
                if (i + 1 < n) K(dof(i, p), dof(i + 1, p)) = K(dof(i + 1, p), dof(i, p)) = -k;
            }
        return K;
    }
    // With the viscous D = alpha M + beta K, or else the loss factor's imaginary stiffness H = eta K.
    OperatorSet operators(bool viscous) const {
        const Eigen::MatrixXd K = stiffness(), M = m * Eigen::MatrixXd::Identity(2 * n, 2 * n);
        Eigen::MatrixXd G = Eigen::MatrixXd::Zero(2 * n, 2 * n);
        for (int i = 0; i < n; ++i) G(dof(i, 0), dof(i, 1)) = -g, G(dof(i, 1), dof(i, 0)) = g;
        const Eigen::MatrixXd pattern = K.cwiseAbs() + M + G.cwiseAbs();
        OperatorSet ops;
        ops.matrices.emplace(Term::stiffness, petsc_matrix(K, pattern));
        ops.matrices.emplace(Term::mass, petsc_matrix(M, pattern));
        ops.matrices.emplace(Term::gyroscopic, petsc_matrix(G, pattern));
        if (viscous) ops.matrices.emplace(Term::damping, petsc_matrix(alpha * M + beta * K, pattern));
        else ops.matrices.emplace(Term::imaginary_stiffness, petsc_matrix(eta * K, K));
        ops.model_mass = m * n;
        return ops;
    }
};

SolveRequest lowest(int n, double scale) {
    SolveRequest r;
    r.n_modes = n;
    r.lambda_scale = scale;
    return r;
}

}  // namespace

TEST_CASE("The damped projected solver finds a spinning chain's closed-form damped whirls", "[eigensolve][damping]") {
    const Chain chain;
    const int n_rest = 8;  // chain modes 1-4 in both planes
    for (const bool structural : {false, true}) {
        const OperatorSet ops = chain.operators(!structural);
        const ProjectedDamped solver(ops, lowest(n_rest, 500.0), n_rest);
        for (const double spin : {0.0, 2 * M_PI * 5}) {
            INFO((structural ? "loss factor eta = 0.02" : "Rayleigh damping") << ", spin " << spin << " rad/s");
            const std::vector<cd> exact = chain.whirls(4, spin, !structural, structural);
            const DampedModes solved = solver.modes_at(spin);
            REQUIRE(solved.modes.size() == exact.size());
            for (size_t i = 0; i < exact.size(); ++i) {
                INFO("mode " << i + 1 << ": " << solved.modes[i].eigenvalue << " against " << exact[i]);
                // The modes at rest to their 1e-10 residual: eigenvalues to its square, the rest round-off.
                CHECK(std::abs(solved.modes[i].eigenvalue - exact[i]) < 1e-9 * std::abs(exact[i]));
                CHECK(solved.modes[i].backward_error < kMaxProjectedResidual);
            }
            if (spin == 0.0 && !structural)  // Rayleigh's zeta_j = alpha / (2 omega_j) + beta omega_j / 2
                CHECK(solved.modes.front().zeta ==
                      Approx(chain.alpha / (2 * chain.omega(1)) + chain.beta * chain.omega(1) / 2).epsilon(1e-9));
            if (spin == 0.0 && structural)  // at resonance as the viscous zeta = eta / 2, to (3/8) eta^2
                CHECK(solved.modes.front().zeta == Approx(chain.eta / 2).epsilon(3 * chain.eta * chain.eta / 8 * 1.01));
        }
    }
}

TEST_CASE("With a damper at one mass the damped branch carries the modes, and its residual bounds their error",
          "[eigensolve][damping]") {
    // Non-proportional damping: one dashpot on mass 3 of the chain (x plane),
    // which the modes at rest do not diagonalise; the basis carries it by the
    // static responses S^-1 D phi. The truth is the full problem solved whole
    // (damped_modes on the 2n DOFs, checked above against closed forms).
    const Chain chain;
    const Eigen::MatrixXd K = chain.stiffness(), M = chain.m * Eigen::MatrixXd::Identity(2 * chain.n, 2 * chain.n);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(2 * chain.n, 2 * chain.n);
    D(chain.dof(2, 0), chain.dof(2, 0)) = 5.0;  // kg/s: zeta 3e-3 to 5e-3 on the x plane's first modes
    const Eigen::MatrixXd pattern = K.cwiseAbs() + M;
    OperatorSet ops;
    ops.matrices.emplace(Term::stiffness, petsc_matrix(K, pattern));
    ops.matrices.emplace(Term::mass, petsc_matrix(M, pattern));
    ops.matrices.emplace(Term::damping, petsc_matrix(D, pattern));
    ops.model_mass = chain.m * chain.n;
    ProjectedDampedModel full;
    full.K = K, full.M = M, full.D = D;
    const DampedModes exact = damped_modes(full, 0.0, 1e-6);
    const DampedModes solved = ProjectedDamped(ops, lowest(8, 500.0), 8).modes_at(0.0);
    REQUIRE(solved.modes.size() >= 4);
    for (size_t i = 0; i < 4; ++i) {  // chain modes 1 and 2, y plane (undamped) and x plane (damped)
        const DampedMode& mode = solved.modes[i];
        const double error =
            std::abs(mode.eigenvalue - exact.modes[i].eigenvalue) / std::abs(exact.modes[i].eigenvalue);
        INFO("mode " << i + 1 << ": zeta " << mode.zeta << ", relative error " << error << ", residual "
                     << mode.backward_error);
        // Measured: errors 1e-12 to 1.4e-10 for residuals 6e-15 to 1.6e-6 (a
        // lightly damped, nearly normal problem: the error is of the order of
        // the residual's square, far below the residual itself).
        CHECK(error < 1e-9);
        CHECK(error <= std::max(mode.backward_error, 1e-11));
        CHECK(mode.zeta > -1e-12);  // the y plane is undamped: zeta 0 to round-off
    }
    CHECK(solved.modes[1].zeta > 1e-3);  // the x plane's first mode is damped
}
