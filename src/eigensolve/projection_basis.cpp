#include "eigensolve/projection_basis.hpp"

#include "eigensolve/petsc_algebra.hpp"

#include <string>

namespace coremodal {
namespace {

// A direction of the basis whose M-Gram eigenvalue is below this fraction of
// the largest (after scaling every column to M-norm 1) is a combination of
// the others to round-off: dropped.
constexpr double kDependentDirection = 1e-14;
// Terms of the static responses' series per mode at rest and force (static_responses).
constexpr int kKrylovDepth = 2;
using Dense = Eigen::MatrixXd;
using KSPHandle = PetscHandle<KSP, KSPDestroy>;

const Progress kQuiet = [](const std::string&) {};

PetscMatrix referenced(Mat A) {
    COREMODAL_PETSC(PetscObjectReference((PetscObject)A));
    return PetscMatrix(A);
}

}  // namespace

// A V, column by column (one process: the sweep refuses mpirun).
Dense apply_columns(Mat A, const Dense& V) {
    Dense out(V.rows(), V.cols());
    PetscVector x, y;
    COREMODAL_PETSC(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, V.rows(), nullptr, x.out()));
    COREMODAL_PETSC(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, V.rows(), nullptr, y.out()));
    for (Eigen::Index j = 0; j < V.cols(); ++j) {
        COREMODAL_PETSC(VecPlaceArray(x, V.col(j).data()));
        COREMODAL_PETSC(VecPlaceArray(y, out.col(j).data()));
        COREMODAL_PETSC(MatMult(A, x, y));
        COREMODAL_PETSC(VecResetArray(x));
        COREMODAL_PETSC(VecResetArray(y));
    }
    return out;
}

Eigen::VectorXd values_of(Vec x) {
    PetscInt n;
    const PetscScalar* a;
    COREMODAL_PETSC(VecGetLocalSize(x, &n));
    COREMODAL_PETSC(VecGetArrayRead(x, &a));
    Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(a, n);
    COREMODAL_PETSC(VecRestoreArrayRead(x, &a));
    return out;
}

Dense m_orthonormal_pass(Mat M, const Dense& V) {
    const Dense gram = V.transpose() * apply_columns(M, V);
    const Eigen::VectorXd scale = gram.diagonal().cwiseSqrt().cwiseInverse();
    const Dense scaled = scale.asDiagonal() * (0.5 * (gram + gram.transpose())) * scale.asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Dense> es(scaled);
    const double largest = es.eigenvalues().maxCoeff();
    Eigen::Index kept = 0;
    while (kept < es.eigenvalues().size() &&
           es.eigenvalues()[es.eigenvalues().size() - 1 - kept] > kDependentDirection * largest)
        ++kept;
    const Dense directions = es.eigenvectors().rightCols(kept);
    const Eigen::VectorXd inv_sqrt = es.eigenvalues().tail(kept).cwiseSqrt().cwiseInverse();
    return V * scale.asDiagonal() * directions * inv_sqrt.asDiagonal();
}

// The modes at rest of the set's stiffness (with any geometric stiffness) and mass.
SolvedModes rest_modes(Mat K, Mat M, double model_mass, const SolveRequest& request, int n_rest) {
    OperatorSet rest;
    rest.matrices[Term::stiffness] = referenced(K);
    rest.matrices[Term::mass] = referenced(M);
    rest.model_mass = model_mass;
    SolveRequest r = request;
    r.n_modes = n_rest;
    return solve_modes(rest, r, kQuiet);
}

std::vector<Eigen::VectorXd> static_responses(Mat K, Mat M, double tau, const std::vector<Mat>& forces,
                                              const std::vector<PetscVector>& rest) {
    PetscMatrix S;
    COREMODAL_PETSC(MatDuplicate(K, MAT_COPY_VALUES, S.out()));
    COREMODAL_PETSC(MatAXPY(S, tau * tau, M, DIFFERENT_NONZERO_PATTERN));
    COREMODAL_PETSC(MatSetOption(S, MAT_SYMMETRIC, PETSC_TRUE));
    COREMODAL_PETSC(MatSetOption(S, MAT_SPD, PETSC_TRUE));
    KSPHandle ksp;
    COREMODAL_PETSC(KSPCreate(PetscObjectComm((PetscObject)K), ksp.out()));
    COREMODAL_PETSC(KSPSetOperators(ksp, S, S));
    COREMODAL_PETSC(KSPSetType(ksp, KSPPREONLY));
    PC pc;
    COREMODAL_PETSC(KSPGetPC(ksp, &pc));
    COREMODAL_PETSC(PCSetType(pc, PCCHOLESKY));
    COREMODAL_PETSC(PCFactorSetMatSolverType(pc, shift_invert_factor_package(PetscObjectComm((PetscObject)K))));
    COREMODAL_PETSC(KSPSetUp(ksp));
    std::vector<Eigen::VectorXd> out;
    PetscVector f, u;
    COREMODAL_PETSC(MatCreateVecs(K, u.out(), f.out()));
    for (Mat A : forces)
        for (const PetscVector& x : rest) {
            COREMODAL_PETSC(MatMult(A, x, f));
            for (int k = 0; k < kKrylovDepth; ++k) {
                if (k > 0) COREMODAL_PETSC(MatMult(M, u, f));
                COREMODAL_PETSC(KSPSolve(ksp, f, u));
                out.push_back(values_of(u));
            }
        }
    return out;
}

std::vector<PetscInt> indices_of(IS is) {
    PetscInt n;
    const PetscInt* a;
    COREMODAL_PETSC(ISGetLocalSize(is, &n));
    COREMODAL_PETSC(ISGetIndices(is, &a));
    std::vector<PetscInt> out(a, a + n);
    COREMODAL_PETSC(ISRestoreIndices(is, &a));
    return out;
}

}  // namespace coremodal
