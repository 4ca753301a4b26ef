// The quadratic (gyroscopic) eigensolver against closed forms: uncoupled
// spinning two-degree-of-freedom rotors (a disc's tilt, or a Jeffcott-like
// point mass pair), whose whirl frequencies are the roots of
// k - omega^2 m = +-omega Omega g; the inertia count of the Hermitian Q(omega);
// and the symmetric solver's modes at rest.
#include "eigensolve/gyroscopic_solver.hpp"

#include "eigensolve/modal_solver.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace coremodal;

namespace {

PetscMatrix petsc_matrix(const Eigen::MatrixXd& A) {
    PetscMatrix m;
    const PetscInt n = A.rows();
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 3, nullptr, m.out()));
    for (PetscInt i = 0; i < n; ++i)
        for (PetscInt j = 0; j < n; ++j)
            if (A(i, j) != 0.0) COREMODAL_PETSC(MatSetValue(m, i, j, A(i, j), INSERT_VALUES));
    COREMODAL_PETSC(MatAssemblyBegin(m, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(m, MAT_FINAL_ASSEMBLY));
    return m;
}

// One block (x, y) per rotor: mass m, stiffness k in both directions,
// gyroscopic coupling g [[0, 1], [-1, 0]] per unit spin.
struct Rotor {
    double m, k, g;
    // The two whirl frequencies at spin Omega (rad/s): omega^2 m -+ omega Omega g - k = 0.
    std::array<double, 2> whirl(double spin) const {
        const double root = std::sqrt(spin * spin * g * g + 4 * k * m);
        return {(root - spin * g) / (2 * m), (root + spin * g) / (2 * m)};
    }
};

OperatorSet rotor_set(const std::vector<Rotor>& rotors, bool gyroscopic = true) {
    const int n = 2 * int(rotors.size());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = K, G = K;
    for (size_t r = 0; r < rotors.size(); ++r) {
        const int i = 2 * int(r);
        K(i, i) = K(i + 1, i + 1) = rotors[r].k;
        M(i, i) = M(i + 1, i + 1) = rotors[r].m;
        G(i, i + 1) = rotors[r].g;
        G(i + 1, i) = -rotors[r].g;
    }
    OperatorSet ops;
    ops.matrices.emplace(Term::stiffness, petsc_matrix(K));
    ops.matrices.emplace(Term::mass, petsc_matrix(M));
    if (gyroscopic) ops.matrices.emplace(Term::gyroscopic, petsc_matrix(G));
    return ops;
}

std::vector<Rotor> twelve_rotors() {
    std::vector<Rotor> r;
    for (int i = 0; i < 12; ++i) r.push_back({1.0 + 0.1 * i, 1e4 * (1 + i) * (1 + i), 0.3 + 0.05 * i});
    return r;
}

std::vector<double> exact_frequencies(const std::vector<Rotor>& rotors, double spin) {
    std::vector<double> f;
    for (const Rotor& r : rotors)
        for (double w : r.whirl(spin)) f.push_back(w);
    std::sort(f.begin(), f.end());
    return f;
}

SolveRequest lowest(int n, double scale) {
    SolveRequest r;
    r.n_modes = n;
    r.lambda_scale = scale;
    return r;
}

const Progress quiet = [](const std::string&) {};

}  // namespace

TEST_CASE("Spinning rotors: the quadratic solver finds the closed-form whirl frequencies, verified and complete",
          "[eigensolve][gyroscopic]") {
    const auto rotors = twelve_rotors();
    const double spin = 2 * M_PI * 20;  // rad/s: splits every pair by omega Omega g / ... of several per cent
    const auto exact = exact_frequencies(rotors, spin);
    const GyroscopicModes solved = solve_gyroscopic(rotor_set(rotors), spin, lowest(10, 1e4), quiet);
    REQUIRE(solved.modes.size() >= 10);
    for (size_t i = 0; i < solved.modes.size(); ++i) {
        INFO("mode " << i);
        // Direct closed form, converged to the 1e-10 residual asked for.
        CHECK(solved.modes[i].omega == Approx(exact[i]).epsilon(1e-9));
        CHECK(solved.modes[i].relative_residual < 1e-10);
    }
    CHECK(solved.verification.complete);
    CHECK(solved.verification.modes_below_shift == long(solved.modes.size()));
    CHECK(solved.verification.max_orthonormality_error < 1e-10);
}

TEST_CASE("The Hermitian inertia count of Q(omega) counts the spinning rotors' modes below omega",
          "[eigensolve][gyroscopic]") {
    const auto rotors = twelve_rotors();
    const double spin = 2 * M_PI * 35;
    const auto exact = exact_frequencies(rotors, spin);
    const OperatorSet ops = rotor_set(rotors);
    // Between every pair of neighbouring exact frequencies the count is the
    // number below: the downward-crossing argument of the solver's header.
    for (size_t i = 0; i + 1 < exact.size(); ++i) {
        const double between = 0.5 * (exact[i] + exact[i + 1]);
        INFO("between modes " << i << " and " << i + 1 << " (" << between << " rad/s)");
        CHECK(count_gyroscopic_below(ops, spin, between) == long(i + 1));
    }
}

TEST_CASE("At rest the quadratic solver gives the symmetric solver's modes", "[eigensolve][gyroscopic]") {
    const auto rotors = twelve_rotors();
    const OperatorSet ops = rotor_set(rotors);
    const GyroscopicModes quadratic = solve_gyroscopic(ops, 0.0, lowest(8, 1e4), quiet);
    const SolvedModes symmetric = solve_modes(rotor_set(rotors, false), lowest(8, 1e4), quiet);
    REQUIRE(quadratic.modes.size() == symmetric.eigenvalues.size());
    for (size_t i = 0; i < quadratic.modes.size(); ++i)
        CHECK(quadratic.modes[i].omega * quadratic.modes[i].omega == Approx(symmetric.eigenvalues[i]).epsilon(1e-10));
}

TEST_CASE("A free spinning disc's tilt precesses at Omega g / m, counted above the rigid line",
          "[eigensolve][gyroscopic]") {
    // k = 0: Q(omega) = -omega^2 m + i omega Omega g J: roots 0 and Omega g / m.
    std::vector<Rotor> rotors = twelve_rotors();
    rotors.push_back({2.0, 0.0, 0.8});
    const double spin = 2 * M_PI * 10;
    const GyroscopicModes solved = solve_gyroscopic(rotor_set(rotors), spin, lowest(6, 1e4), quiet);
    const double precession = spin * 0.8 / 2.0;
    const bool found = std::any_of(solved.modes.begin(), solved.modes.end(),
                                   [&](const GyroscopicMode& m) { return std::abs(m.omega / precession - 1) < 1e-9; });
    CHECK(found);
    CHECK(solved.verification.complete);
    CHECK(solved.verification.max_relative_residual < 1e-10);
}

TEST_CASE("The quadratic solver refuses a damping term and a band", "[eigensolve][gyroscopic]") {
    OperatorSet ops = rotor_set(twelve_rotors());
    SolveRequest band = lowest(4, 1e4);
    band.lambda_min = 0.0;
    band.lambda_max = 1e6;
    CHECK_THROWS_WITH(solve_gyroscopic(ops, 10.0, band, quiet), Catch::Contains("band"));
    ops.matrices.emplace(Term::damping, petsc_matrix(Eigen::MatrixXd::Identity(24, 24)));
    CHECK_THROWS_WITH(solve_gyroscopic(ops, 10.0, lowest(4, 1e4), quiet), Catch::Contains("damping"));
}
