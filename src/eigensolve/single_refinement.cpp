#include "eigensolve/single_refinement.hpp"

#include "eigensolve/sparse_block_product.hpp"

#include "common/error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace coremodal {

namespace {

using Dense = Eigen::MatrixXd;

// Directions whose Gram eigenvalue falls below this share of the largest are
// dependent (X and A^-1 M X nearly share a converged mode's direction).
constexpr double kDependentGramShare = 1e-20;

// A B for a one-process AIJ A (SparseBlockProduct) or any other matrix
// (one MatMult a column).
Dense times(Mat A, const Dense& B, SparseBlockProduct& product) {
    Dense out(B.rows(), B.cols());
    if (SparseBlockProduct::handles(A)) {
        product(A, int(B.cols()), B.data(), out.data());
        return out;
    }
    Vec x = nullptr, y = nullptr;
    COREMODAL_PETSC(MatCreateVecs(A, &x, &y));
    for (Eigen::Index c = 0; c < B.cols(); ++c) {
        COREMODAL_PETSC(VecPlaceArray(x, B.col(c).data()));
        COREMODAL_PETSC(VecPlaceArray(y, out.col(c).data()));
        COREMODAL_PETSC(MatMult(A, x, y));
        COREMODAL_PETSC(VecResetArray(x));
        COREMODAL_PETSC(VecResetArray(y));
    }
    VecDestroy(&x);
    VecDestroy(&y);
    return out;
}

// An M-orthonormal basis of B's columns (one pass: the Gram matrix's
// eigenvectors, dependent directions dropped; twice for round-off).
Dense m_orthonormal(Mat M, const Dense& B, SparseBlockProduct& product) {
    Dense V = B;
    for (int pass = 0; pass < 2; ++pass) {
        const Dense gram = V.transpose() * times(M, V, product);
        const Eigen::SelfAdjointEigenSolver<Dense> es(0.5 * (gram + gram.transpose()));
        const double largest = es.eigenvalues().maxCoeff();
        Eigen::Index kept = 0;
        const Eigen::Index size = es.eigenvalues().size();
        while (kept < size && es.eigenvalues()[size - 1 - kept] > kDependentGramShare * largest) ++kept;
        V = V * es.eigenvectors().rightCols(kept) * es.eigenvalues().tail(kept).cwiseSqrt().cwiseInverse().asDiagonal();
    }
    return V;
}

// The largest relative residual ||K x - lambda M x|| / (||K||_1 ||x||) of
// the columns of X.
double largest_residual(const Dense& KX, const Dense& MX, const Dense& X, const Eigen::VectorXd& lambdas,
                        double K_norm) {
    double worst = 0;
    for (Eigen::Index j = 0; j < X.cols(); ++j)
        worst = std::max(worst, (KX.col(j) - lambdas[j] * MX.col(j)).norm() / (K_norm * X.col(j).norm()));
    return worst;
}

}  // namespace

double pass_backward_error() {
    PetscReal value = kPassBackwardError;
    PetscBool given = PETSC_FALSE;
    COREMODAL_PETSC(PetscOptionsGetReal(nullptr, nullptr, "-factor_single_pass_error", &value, &given));
    if (given && !(value > 0))
        throw InputError("-factor_single_pass_error " + std::to_string(value) +
                         ": expected a positive backward error (1e-13 refines every pass fully)");
    return value;
}

double single_lanczos_tolerance() {
    PetscReal value = kSingleLanczosTolerance;
    PetscBool given = PETSC_FALSE;
    COREMODAL_PETSC(PetscOptionsGetReal(nullptr, nullptr, "-factor_single_lanczos_tolerance", &value, &given));
    return value;
}

int refine_pairs_in_double(SingleLdlt& F, Mat K, Mat M, std::vector<double>& lambdas,
                           std::vector<PetscVector>& vectors) {
    const Eigen::Index k = Eigen::Index(vectors.size());
    if (k == 0) return 0;
    PetscInt n = 0;
    COREMODAL_PETSC(VecGetLocalSize(vectors[0], &n));
    Dense X(n, k);
    for (Eigen::Index j = 0; j < k; ++j) {
        const PetscScalar* x = nullptr;
        COREMODAL_PETSC(VecGetArrayRead(vectors[j], &x));
        std::copy(x, x + n, X.col(j).data());
        COREMODAL_PETSC(VecRestoreArrayRead(vectors[j], &x));
    }
    PetscReal K_norm = 0;
    COREMODAL_PETSC(MatNorm(K, NORM_1, &K_norm));
    SparseBlockProduct product;
    Eigen::VectorXd values = Eigen::Map<const Eigen::VectorXd>(lambdas.data(), k);
    Dense MX = times(M, X, product);
    int steps = 0;
    for (;;) {
        const double worst = largest_residual(times(K, X, product), MX, X, values, K_norm);
        if (steps >= kMostRitzSteps || worst <= kRitzResidual) break;
        ++steps;
        Dense basis(n, 2 * k);
        basis.leftCols(k) = X;
        Dense Y(n, k);
        F.solve(int(k), MX.data(), Y.data(), kRefinedBackwardError);
        basis.rightCols(k) = Y;
        const Dense Q = m_orthonormal(M, basis, product);
        COREMODAL_ASSERT(Q.cols() >= k);
        // Q is M-orthonormal: the projected pencil is (Q^T K Q, I).
        const Dense H = Q.transpose() * times(K, Q, product);
        const Eigen::SelfAdjointEigenSolver<Dense> es(0.5 * (H + H.transpose()));
        values = es.eigenvalues().head(k);
        X = Q * es.eigenvectors().leftCols(k);
        MX = times(M, X, product);
    }
    for (Eigen::Index j = 0; j < k; ++j) {
        lambdas[j] = values[j];
        PetscScalar* x = nullptr;
        COREMODAL_PETSC(VecGetArray(vectors[j], &x));
        std::copy(X.col(j).data(), X.col(j).data() + n, x);
        COREMODAL_PETSC(VecRestoreArray(vectors[j], &x));
    }
    return steps;
}

}  // namespace coremodal
