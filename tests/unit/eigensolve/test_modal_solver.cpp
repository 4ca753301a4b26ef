// The symmetric solver's one-factorization path (issue 19) against a closed
// form: a fixed–fixed chain of n equal masses m and springs k, whose
// eigenvalues are lambda_j = (4 k / m) sin^2(j pi / (2 (n + 1))), j = 1..n.
// A prediction of the lowest eigenvalues places one LDL^T factor in the gap
// above the wanted modes; a prediction too low or too high must still give
// the same modes, proven complete, by the fallbacks.
#include "eigensolve/modal_solver.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>
#include <vector>

using namespace coremodal;

namespace {

constexpr int kChain = 300;
constexpr double kSpring = 1e6, kMass = 0.5;

double chain_eigenvalue(int j) {
    const double s = std::sin(j * M_PI / (2.0 * (kChain + 1)));
    return 4 * kSpring / kMass * s * s;
}

// K and M on one sparsity pattern, as the assembly makes them (the solver's
// K - sigma M relies on it): M's off-diagonal entries are stored zeros.
PetscMatrix chain_matrix(double diagonal, double off_diagonal) {
    PetscMatrix A;
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, kChain, kChain, 3, nullptr, A.out()));
    for (PetscInt i = 0; i < kChain; ++i) {
        COREMODAL_PETSC(MatSetValue(A, i, i, diagonal, INSERT_VALUES));
        if (i > 0) COREMODAL_PETSC(MatSetValue(A, i, i - 1, off_diagonal, INSERT_VALUES));
        if (i + 1 < kChain) COREMODAL_PETSC(MatSetValue(A, i, i + 1, off_diagonal, INSERT_VALUES));
    }
    COREMODAL_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    return A;
}

OperatorSet chain() {
    OperatorSet ops;
    ops.matrices.emplace(Term::stiffness, chain_matrix(2 * kSpring, -kSpring));
    ops.matrices.emplace(Term::mass, chain_matrix(kMass, 0));
    return ops;
}

// The lowest `count` eigenvalues, each scaled by `factor` (a prediction off by that much).
std::vector<double> predicted(int count, double factor) {
    std::vector<double> out;
    for (int j = 1; j <= count; ++j) out.push_back(factor * chain_eigenvalue(j));
    return out;
}

SolveRequest lowest(int n_modes, std::vector<double> prediction) {
    SolveRequest r;
    r.n_modes = n_modes;
    r.lambda_scale = chain_eigenvalue(1);
    r.predicted_eigenvalues = std::move(prediction);
    return r;
}

// The closed form to 1e-9: SLEPc's tolerance 1e-10 on the residual gives
// eigenvalues far closer (the error is quadratic in the residual), and the
// closed form's own round-off is ~1e-15.
void require_chain_modes(const SolvedModes& s, int n_modes) {
    REQUIRE(int(s.eigenvalues.size()) == n_modes);
    for (int j = 1; j <= n_modes; ++j) CHECK(s.eigenvalues[j - 1] == Approx(chain_eigenvalue(j)).epsilon(1e-9));
    CHECK(s.verification.complete);
    CHECK(s.verification.negative_pivots_at_shift == s.verification.modes_below_shift);
    CHECK(s.verification.max_relative_residual < 1e-8);
    CHECK(s.verification.max_orthonormality_error < 1e-8);
}

}  // namespace

TEST_CASE("One LDL^T factor at the predicted band edge solves and counts", "[eigensolve][one_factor]") {
    const OperatorSet ops = chain();
    const int wanted = 8;
    std::vector<std::string> log;
    const auto said = [&](const std::string& words) {
        return std::any_of(log.begin(), log.end(), [&](const std::string& line) { return line.find(words) != std::string::npos; });
    };
    const Progress keep = [&](const std::string& line) { log.push_back(line); };

    SECTION("An exact prediction: the count is taken at the shift, halfway into the gap after the wanted modes") {
        const SolvedModes s = solve_modes(ops, lowest(wanted, predicted(12, 1.0)), keep);
        require_chain_modes(s, wanted);
        CHECK(s.verification.check_shift == Approx(0.5 * (chain_eigenvalue(8) + chain_eigenvalue(9))));
        CHECK(s.verification.negative_pivots_at_shift == wanted);
        for (const std::string& line : log) CHECK(line.find("missed") == std::string::npos);
    }
    SECTION("A prediction too low (too few modes below the shift) re-shifts to the edge found, and says so") {
        const SolvedModes s = solve_modes(ops, lowest(wanted, predicted(12, 0.8)), keep);
        require_chain_modes(s, wanted);
        CHECK(s.verification.negative_pivots_at_shift == wanted);
        CHECK(said("the shift missed"));
    }
    SECTION("A prediction too high (many more modes below the shift) re-shifts to the edge found, and says so") {
        const SolvedModes s = solve_modes(ops, lowest(wanted, predicted(12, 4.0)), keep);
        require_chain_modes(s, wanted);
        CHECK(said("the shift missed"));
    }
    SECTION("A prediction a little high computes the extra modes below the shift and reports the wanted ones") {
        const SolvedModes s = solve_modes(ops, lowest(wanted, predicted(12, 1.15)), keep);
        require_chain_modes(s, wanted);
        CHECK(s.verification.negative_pivots_at_shift > wanted);
        for (const std::string& line : log) CHECK(line.find("missed") == std::string::npos);
    }
    SECTION("Without a prediction the negative shift and a second count give the same modes") {
        const SolvedModes s = solve_modes(ops, lowest(wanted, {}), keep);
        require_chain_modes(s, wanted);
    }
}
