// The block Lanczos eigensolver (issue 19) against closed forms: spring
// chains, whose eigenvalues are known exactly, and a diagonal pencil with
// few distinct eigenvalues of high multiplicity. The solver's promises: the
// lowest eigenpairs to SLEPc's accuracy, every member of a multiple
// eigenvalue (a block holds them all at once), M-orthonormal vectors, and a
// Krylov space that becomes invariant handled, not divided by zero.
#include "eigensolve/block_lanczos.hpp"
#include "eigensolve/modal_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

using namespace coremodal;

namespace {

constexpr double kSpring = 1e6, kMass = 0.5;

// `copies` uncoupled chains of `masses` masses each, on one sparsity
// pattern for K and M (stored zeros in M, as the assembly makes them):
// held at both ends by springs (fixed), or with free ends.
PetscMatrix chains_matrix(int copies, int masses, bool fixed, bool mass) {
    const PetscInt n = PetscInt(copies) * masses;
    PetscMatrix A;
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 3, nullptr, A.out()));
    for (PetscInt i = 0; i < n; ++i) {
        const bool first = i % masses == 0, last = i % masses == masses - 1;
        const double diagonal = mass ? kMass : ((first || last) && !fixed ? kSpring : 2 * kSpring);
        COREMODAL_PETSC(MatSetValue(A, i, i, diagonal, INSERT_VALUES));
        if (!first) COREMODAL_PETSC(MatSetValue(A, i, i - 1, mass ? 0.0 : -kSpring, INSERT_VALUES));
        if (!last) COREMODAL_PETSC(MatSetValue(A, i, i + 1, mass ? 0.0 : -kSpring, INSERT_VALUES));
    }
    COREMODAL_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    return A;
}

OperatorSet chains(int copies, int masses, bool fixed) {
    OperatorSet ops;
    ops.matrices.emplace(Term::stiffness, chains_matrix(copies, masses, fixed, false));
    ops.matrices.emplace(Term::mass, chains_matrix(copies, masses, fixed, true));
    return ops;
}

// Fixed ends: lambda_j = (4k/m) sin^2(j pi / (2 (N + 1))), j = 1 ... N.
// Free ends: lambda_j = (4k/m) sin^2(j pi / (2 N)), j = 0 ... N - 1.
double chain_eigenvalue(int masses, int j, bool fixed) {
    const double s = std::sin(j * M_PI / (2.0 * (fixed ? masses + 1 : masses)));
    return 4 * kSpring / kMass * s * s;
}

// Every progress line, to see which method ran.
struct Said {
    std::vector<std::string> lines;
    Progress printer() {
        return [this](const std::string& line) { lines.push_back(line); };
    }
    bool any(const std::string& text) const {
        for (const auto& l : lines)
            if (l.find(text) != std::string::npos) return true;
        return false;
    }
};

void require_verified(const SolvedModes& s) {
    CHECK(s.verification.complete);
    CHECK(s.verification.negative_pivots_at_shift == s.verification.modes_below_shift);
    CHECK(s.verification.max_relative_residual < 1e-8);
    CHECK(s.verification.max_orthonormality_error < 1e-8);
}

}  // namespace

// A membrane of 200 x 150 masses on a square grid of springs, held at its
// edge: lambda_pq = (4k/m) (sin^2(p pi / 402) + sin^2(q pi / 302)). 30,000
// unknowns: above the size where the solver takes the block method. Its
// condition number (about 2e4, against 1.5e9 for a chain as long) lets the
// closed form hold to 1e-9, as SLEPc's path is held (test_modal_solver.cpp):
// the tolerance 1e-10 on the residual gives eigenvalues far closer.
constexpr int kGridX = 200, kGridY = 150;

PetscMatrix membrane_matrix(bool mass) {
    const PetscInt n = PetscInt(kGridX) * kGridY;
    PetscMatrix A;
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 5, nullptr, A.out()));
    for (int y = 0; y < kGridY; ++y)
        for (int x = 0; x < kGridX; ++x) {
            const PetscInt i = PetscInt(y) * kGridX + x;
            COREMODAL_PETSC(MatSetValue(A, i, i, mass ? kMass : 4 * kSpring, INSERT_VALUES));
            const double off = mass ? 0.0 : -kSpring;
            if (x > 0) COREMODAL_PETSC(MatSetValue(A, i, i - 1, off, INSERT_VALUES));
            if (x + 1 < kGridX) COREMODAL_PETSC(MatSetValue(A, i, i + 1, off, INSERT_VALUES));
            if (y > 0) COREMODAL_PETSC(MatSetValue(A, i, i - kGridX, off, INSERT_VALUES));
            if (y + 1 < kGridY) COREMODAL_PETSC(MatSetValue(A, i, i + kGridX, off, INSERT_VALUES));
        }
    COREMODAL_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    return A;
}

OperatorSet membrane() {
    OperatorSet ops;
    ops.matrices.emplace(Term::stiffness, membrane_matrix(false));
    ops.matrices.emplace(Term::mass, membrane_matrix(true));
    return ops;
}

std::vector<double> membrane_eigenvalues(int count) {
    std::vector<double> all;
    for (int p = 1; p <= 20; ++p)
        for (int q = 1; q <= 20; ++q) {
            const double sx = std::sin(p * M_PI / (2.0 * (kGridX + 1))), sy = std::sin(q * M_PI / (2.0 * (kGridY + 1)));
            all.push_back(4 * kSpring / kMass * (sx * sx + sy * sy));
        }
    std::sort(all.begin(), all.end());
    all.resize(count);
    return all;
}

TEST_CASE("Block Lanczos finds a membrane's lowest modes, proven complete", "[eigensolve][block_lanczos]") {
    constexpr int kModes = 12;
    const OperatorSet ops = membrane();
    const std::vector<double> exact = membrane_eigenvalues(kModes + 4);
    SolveRequest request;
    request.n_modes = kModes;
    request.lambda_scale = exact[0];
    Said said;
    const SolvedModes s = solve_modes(ops, request, said.printer());
    CHECK(said.any("block Lanczos: "));
    REQUIRE(int(s.eigenvalues.size()) == kModes);
    for (int j = 0; j < kModes; ++j) CHECK(s.eigenvalues[j] == Approx(exact[j]).epsilon(1e-9));
    require_verified(s);
}

// Three equal free chains: every eigenvalue three times over, the rigid
// one (0) included. A one-vector Krylov space meets the second and third
// copies only through round-off; a block holds all three. A free chain of
// 7,000 masses has condition number lambda_max / lambda_1 = 2e7, so
// round-off alone may move lambda_1 by about 1e-16 x 2e7: the closed form
// to 1e-8.
TEST_CASE("Block Lanczos finds every member of a threefold eigenvalue, rigid ones too", "[eigensolve][block_lanczos]") {
    constexpr int kMasses = 7000, kCopies = 3;
    const OperatorSet ops = chains(kCopies, kMasses, false);
    SolveRequest request;
    request.n_modes = 9;
    request.lambda_scale = chain_eigenvalue(kMasses, 1, false);
    Said said;
    const SolvedModes s = solve_modes(ops, request, said.printer());
    CHECK(said.any("block Lanczos: "));
    REQUIRE(s.eigenvalues.size() == 9);
    for (int i = 0; i < kCopies; ++i) CHECK(std::abs(s.eigenvalues[i]) < 1e-9 * request.lambda_scale);
    for (int j = 1; j <= 2; ++j)
        for (int i = 0; i < kCopies; ++i)
            CHECK(s.eigenvalues[j * kCopies + i] == Approx(chain_eigenvalue(kMasses, j, false)).epsilon(1e-8));
    require_verified(s);
}

// K = diag(1, 2, 3, 4, 5, 1, 2, ...), M = I: five distinct eigenvalues,
// each 80 times over. From a random block of b vectors the Krylov space
// holds at most 5 b directions and then stops growing: the block's new
// directions are round-off, which the method replaces by random ones
// instead of normalising noise. The ten lowest are all 1.
TEST_CASE("Block Lanczos carries on when its Krylov space becomes invariant", "[eigensolve][block_lanczos]") {
    constexpr PetscInt kN = 400;
    constexpr double kSigma = -0.5;
    PetscMatrix K, M, A, F;
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, kN, kN, 1, nullptr, K.out()));
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, kN, kN, 1, nullptr, M.out()));
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, kN, kN, 1, nullptr, A.out()));
    for (PetscInt i = 0; i < kN; ++i) {
        const double d = 1.0 + double(i % 5);
        COREMODAL_PETSC(MatSetValue(K, i, i, d, INSERT_VALUES));
        COREMODAL_PETSC(MatSetValue(M, i, i, 1.0, INSERT_VALUES));
        COREMODAL_PETSC(MatSetValue(A, i, i, d - kSigma, INSERT_VALUES));
    }
    for (Mat X : {K.get(), M.get(), A.get()}) {
        COREMODAL_PETSC(MatAssemblyBegin(X, MAT_FINAL_ASSEMBLY));
        COREMODAL_PETSC(MatAssemblyEnd(X, MAT_FINAL_ASSEMBLY));
    }
    COREMODAL_PETSC(factor_symmetric(A, MATSOLVERCHOLMOD, F));

    // An expert's block or basis the method cannot work with is refused by name.
    for (auto [option, value] : {std::pair{"-block_lanczos_bs", "0"}, std::pair{"-block_lanczos_ncv", "20"}}) {
        COREMODAL_PETSC(PetscOptionsSetValue(nullptr, option, value));
        CHECK_THROWS_WITH(block_lanczos_lowest(F, M, kSigma, {10, 1e-10, 50}),
                          Catch::Contains("expected a block of at least 1 and a basis of at least"));
        COREMODAL_PETSC(PetscOptionsClearValue(nullptr, option));
    }

    const BlockLanczosResult r = block_lanczos_lowest(F, M, kSigma, {10, 1e-10, 50});
    REQUIRE(r.eigenvalues.size() >= 10);
    for (int i = 0; i < 10; ++i) CHECK(r.eigenvalues[i] == Approx(1.0).epsilon(1e-12));
    // The space stops growing after five blocks; it must not take many more.
    CHECK(r.blocks_solved <= 7);
    // M-orthonormal, and eigenvectors: K x = x.
    PetscVector Kx;
    COREMODAL_PETSC(VecDuplicate(r.vectors[0], Kx.out()));
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j <= i; ++j) {
            PetscScalar d;
            COREMODAL_PETSC(VecDot(r.vectors[i], r.vectors[j], &d));
            CHECK(std::abs(d - (i == j ? 1.0 : 0.0)) < 1e-12);
        }
        COREMODAL_PETSC(MatMult(K, r.vectors[i], Kx));
        COREMODAL_PETSC(VecAXPY(Kx, -1.0, r.vectors[i]));
        PetscReal norm;
        COREMODAL_PETSC(VecNorm(Kx, NORM_2, &norm));
        CHECK(norm < 1e-10);
    }
}

// The one-factor path in blocks: a prediction of the membrane's lowest
// eigenvalues places one MUMPS LDL^T factor in the gap above the wanted
// modes; its negative pivots count them, and block Lanczos finds them as the
// negative Ritz values of the indefinite operator. A prediction half the
// truth places the shift below the wanted modes: the solver says so and
// falls back to the negative shift and a second count, with the same modes.
TEST_CASE("Block Lanczos on one LDL^T factor at the predicted edge solves and counts", "[eigensolve][block_lanczos]") {
    constexpr int kModes = 12;
    const OperatorSet ops = membrane();
    const std::vector<double> exact = membrane_eigenvalues(kModes + 6);
    for (double factor : {1.0, 0.5}) {
        SECTION("prediction " + std::to_string(factor) + " x the truth") {
            SolveRequest request;
            request.n_modes = kModes;
            request.lambda_scale = exact[0];
            for (double lambda : exact) request.predicted_eigenvalues.push_back(factor * lambda);
            Said said;
            const SolvedModes s = solve_modes(ops, request, said.printer());
            CHECK(said.any("one factor for the solve (block Lanczos) and the count"));
            CHECK(said.any("block Lanczos: "));
            CHECK(said.any("the shift missed") == (factor != 1.0));
            REQUIRE(int(s.eigenvalues.size()) == kModes);
            for (int j = 0; j < kModes; ++j) CHECK(s.eigenvalues[j] == Approx(exact[j]).epsilon(1e-9));
            require_verified(s);
            if (factor == 1.0) {
                // The count came from the one factor, at the predicted gap's middle.
                CHECK(s.verification.check_shift == Approx(0.5 * (exact[kModes - 1] + exact[kModes])));
                CHECK(s.verification.negative_pivots_at_shift == kModes);
            }
        }
    }
}

namespace {

// The mode (p, q) of a membrane `stretch` times as long and wide, sampled
// at this one's masses: sin(p pi (x + 1) / (s (X + 1))) sin(q pi (y + 1) /
// (s (Y + 1))), as another model of the same scene would predict it (at
// stretch 1 the exact eigenvector of the grid; off it, every mode of the
// grid is in it, as in a prediction from another mesh).
PetscVector membrane_mode(int p, int q, double stretch) {
    PetscVector v;
    COREMODAL_PETSC(VecCreateSeq(PETSC_COMM_SELF, PetscInt(kGridX) * kGridY, v.out()));
    PetscScalar* x;
    COREMODAL_PETSC(VecGetArray(v, &x));
    for (int y = 0; y < kGridY; ++y)
        for (int i = 0; i < kGridX; ++i)
            x[PetscInt(y) * kGridX + i] = std::sin(p * M_PI * (i + 1) / (stretch * (kGridX + 1.0))) *
                                          std::sin(q * M_PI * (y + 1) / (stretch * (kGridY + 1.0)));
    COREMODAL_PETSC(VecRestoreArray(v, &x));
    return v;
}

// The (p, q) of the membrane's `count` lowest modes, in order.
std::vector<std::pair<int, int>> membrane_lowest_indices(int count) {
    std::vector<std::tuple<double, int, int>> all;
    for (int p = 1; p <= 20; ++p)
        for (int q = 1; q <= 20; ++q) {
            const double sx = std::sin(p * M_PI / (2.0 * (kGridX + 1))), sy = std::sin(q * M_PI / (2.0 * (kGridY + 1)));
            all.emplace_back(sx * sx + sy * sy, p, q);
        }
    std::sort(all.begin(), all.end());
    std::vector<std::pair<int, int>> out;
    for (int k = 0; k < count; ++k) out.emplace_back(std::get<1>(all[k]), std::get<2>(all[k]));
    return out;
}

// "block Lanczos: N passes ..." -> N.
int passes_said(const Said& said) {
    for (const auto& l : said.lines)
        if (l.rfind("block Lanczos: ", 0) == 0) return std::stoi(l.substr(15));
    return -1;
}

}  // namespace

// A start from predicted modes changes how fast the space converges, never
// what is accepted: the same eigenvalues (1e-9 relative: the residual test
// 1e-10 holds both far closer) and the same proof. The exact modes of the
// grid (stretch 1) converge in a few passes. The modes of a membrane 2 %
// larger took 62 passes against a random start's 15 (their error lies in
// the grid's high modes, far from the wanted ones' neighbours) and stopped
// at 1.2e-8 relative residual; guarded, that start is dropped after the
// passes a random start takes (predicted_start_passes) and the random
// start's own steps follow: its modes, to its residual. On case 03's solid
// the harmonic level's modes take 6-7 passes against 13-14
// (bench/results/log.md, sessions 22 and 23).
TEST_CASE("Block Lanczos started from predicted modes finds the same modes", "[eigensolve][block_lanczos]") {
    constexpr int kModes = 12;
    const OperatorSet ops = membrane();
    const std::vector<double> exact = membrane_eigenvalues(kModes);
    SolveRequest request;
    request.n_modes = kModes;
    request.lambda_scale = exact[0];
    Said cold_said;
    const SolvedModes cold = solve_modes(ops, request, cold_said.printer());
    const int cold_passes = passes_said(cold_said);
    REQUIRE(cold_passes > 0);
    for (const double stretch : {1.0, 1.02}) {
        // A loop, not Catch2 SECTIONs: a SECTION would rerun the cold solve above.
        INFO("the modes of a membrane " << stretch << " times as large");
        auto predicted = std::make_shared<std::vector<PetscVector>>();
        for (auto [p, q] : membrane_lowest_indices(kModes + 4)) predicted->push_back(membrane_mode(p, q, stretch));
        SolveRequest warm_request = request;
        warm_request.predicted_vectors = predicted;
        Said warm_said;
        const SolvedModes warm = solve_modes(ops, warm_request, warm_said.printer());
        CHECK(warm_said.any("started from 16 predicted mode(s)"));
        REQUIRE(warm.eigenvalues.size() == cold.eigenvalues.size());
        for (std::size_t j = 0; j < cold.eigenvalues.size(); ++j)
            CHECK(warm.eigenvalues[j] == Approx(cold.eigenvalues[j]).epsilon(1e-9));
        require_verified(warm);
        const int warm_passes = passes_said(warm_said);
        INFO("stretch " << stretch << ": " << warm_passes << " passes against " << cold_passes);
        const bool dropped = warm_said.any("then from a random start");
        if (stretch == 1.0) {
            CHECK_FALSE(dropped);
            CHECK(warm_passes < cold_passes / 2);
        } else {
            // Dropped after two fillings of the basis (16 vectors a
            // block, 7 blocks: 14 passes), then the random start's own.
            CHECK(dropped);
            CHECK(warm_said.any("that had not converged in 14 passes"));
            CHECK(warm_passes == 14 + cold_passes);
        }
    }
}
