// The one-process sparse-times-block product of block Lanczos
// (eigensolve/sparse_block_product.hpp) against PETSc's MatMatMult on a
// random sparse matrix, for block widths that use every chunk of columns
// (16, 8, 4, 1) and a width the product meets twice in a row (its scratch
// space reused).
#include "eigensolve/sparse_block_product.hpp"

#include "common/petsc_handle.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using namespace coremodal;

namespace {

// n x n with ~6 random entries a row (and the diagonal), values in [-1, 1].
PetscMatrix random_sparse(PetscInt n, std::mt19937_64& random) {
    std::uniform_int_distribution<PetscInt> column(0, n - 1);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    PetscMatrix A;
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 7, nullptr, A.out()));
    for (PetscInt i = 0; i < n; ++i) {
        COREMODAL_PETSC(MatSetValue(A, i, i, value(random), INSERT_VALUES));
        for (int k = 0; k < 6; ++k) COREMODAL_PETSC(MatSetValue(A, i, column(random), value(random), INSERT_VALUES));
    }
    COREMODAL_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    return A;
}

// A X by PETSc (column-major, n x cols).
std::vector<double> petsc_product(Mat A, PetscInt n, int cols, std::vector<double>& x) {
    PetscMatrix X, Y;
    COREMODAL_PETSC(MatCreateSeqDense(PETSC_COMM_SELF, n, cols, x.data(), X.out()));
    COREMODAL_PETSC(MatMatMult(A, X, MAT_INITIAL_MATRIX, PETSC_DEFAULT, Y.out()));
    const double* y = nullptr;
    COREMODAL_PETSC(MatDenseGetArrayRead(Y, &y));
    std::vector<double> out(y, y + size_t(n) * size_t(cols));
    COREMODAL_PETSC(MatDenseRestoreArrayRead(Y, &y));
    return out;
}

}  // namespace

TEST_CASE("The block product of a sparse matrix equals PETSc's for every block width", "[eigensolve][block_lanczos]") {
    std::mt19937_64 random(20261127u);
    const PetscInt n = 997;  // prime: no width divides it
    const PetscMatrix A = random_sparse(n, random);
    REQUIRE(SparseBlockProduct::handles(A));
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    SparseBlockProduct product;
    for (int cols : {1, 3, 4, 13, 16, 16, 21, 32}) {
        std::vector<double> x(size_t(n) * size_t(cols)), y(x.size(), 0.0);
        for (double& v : x) v = value(random);
        product(A, cols, x.data(), y.data());
        const std::vector<double> expected = petsc_product(A, n, cols, x);
        double worst = 0, largest = 0;
        for (size_t i = 0; i < y.size(); ++i) {
            worst = std::max(worst, std::abs(y[i] - expected[i]));
            largest = std::max(largest, std::abs(expected[i]));
        }
        INFO(cols << " columns");
        // The same seven products summed per entry, perhaps in another
        // order: a few units of round-off of the largest entry.
        CHECK(worst <= 1e-14 * largest);
    }
}

TEST_CASE("A parallel matrix is left to PETSc's product", "[eigensolve][block_lanczos]") {
    PetscMatrix A;
    COREMODAL_PETSC(MatCreate(PETSC_COMM_SELF, A.out()));
    COREMODAL_PETSC(MatSetSizes(A, 4, 4, 4, 4));
    COREMODAL_PETSC(MatSetType(A, MATMPIAIJ));
    CHECK_FALSE(SparseBlockProduct::handles(A));
}
