#include "eigensolve/petsc_algebra.hpp"

#include "eigensolve/modal_solver.hpp"  // shift_invert_factor_package

#include "common/error.hpp"
#include "common/format.hpp"
#include "common/free_memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace coremodal {

double vector_norm(Vec x) {
    PetscReal n;
    COREMODAL_PETSC(VecNorm(x, NORM_2, &n));
    return n;
}

double norm_1(Mat A) {
    PetscReal n;
    COREMODAL_PETSC(MatNorm(A, NORM_1, &n));
    return n;
}

double bilinear_form(Mat A, Vec y, Vec x) {
    PetscVector Ax;
    COREMODAL_PETSC(VecDuplicate(x, Ax.out()));
    COREMODAL_PETSC(MatMult(A, x, Ax));
    PetscScalar v;
    COREMODAL_PETSC(VecDot(Ax, y, &v));
    return PetscRealPart(v);
}

PetscMatrix shifted(Mat K, Mat M, double sigma) {
    PetscMatrix A;
    COREMODAL_PETSC(MatDuplicate(K, MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -sigma, M, SAME_NONZERO_PATTERN));
    return A;
}

namespace {

// The memory the run may still take, MB: free_memory_mb (the machine's and
// its control group's), or the user's -max_memory_mb when smaller (a
// machine shared with other jobs).
double memory_allowed_mb() {
    double allowed = free_memory_mb();
    // Read as text: PETSc's own number reader answers "abc" with its error 63.
    char text[256] = "";
    PetscBool given = PETSC_FALSE;
    COREMODAL_PETSC(PetscOptionsGetString(nullptr, nullptr, "-max_memory_mb", text, sizeof text, &given));
    if (!given) return allowed;
    char* end = nullptr;
    const double users_cap = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(users_cap > 0) || !std::isfinite(users_cap))
        throw InputError("-max_memory_mb " + std::string(*text ? text : "(no value)") +
                         ": expected the memory this run may take, a positive number of MB (e.g. -max_memory_mb 6000)");
    return allowed > 0 ? std::min(allowed, double(users_cap)) : double(users_cap);
}

// MUMPS out of core when its estimate does not fit (factor_fits_in_memory).
void out_of_core_if_too_large(Mat F) {
    PetscInt estimate_mb = 0, out_of_core_mb = 0;
    COREMODAL_PETSC(MatMumpsGetInfog(F, 17, &estimate_mb));
    COREMODAL_PETSC(MatMumpsGetInfog(F, 27, &out_of_core_mb));
    if (factor_goes_out_of_core(PetscObjectComm((PetscObject)F), double(estimate_mb), double(out_of_core_mb)))
        COREMODAL_PETSC(MatMumpsSetIcntl(F, 22, 1));
}

}  // namespace

bool factor_goes_out_of_core(MPI_Comm comm, double estimate_mb, double out_of_core_mb) {
    PetscInt users_value = 0;
    PetscBool users_choice = PETSC_FALSE;
    COREMODAL_PETSC(PetscOptionsGetInt(nullptr, nullptr, "-mat_mumps_icntl_22", &users_value, &users_choice));
    if (users_choice) return users_value == 1;
    double allowed_mb = memory_allowed_mb();
    MPI_Bcast(&allowed_mb, 1, MPI_DOUBLE, 0, comm);
    if (factor_fits_in_memory(estimate_mb, allowed_mb)) return false;
    // Out of core needs less, INFOG(27) (MUMPS 5 users' guide, section 6.2):
    // when even that does not fit in the memory the machine or the job has,
    // the factor would fail deep inside MUMPS (or the process be killed):
    // say so before it starts.
    // Against the machine's or the job's memory, not a user's -max_memory_mb:
    // that cap asks for the factor on disk, which is what follows.
    double physical_mb = free_memory_mb();
    MPI_Bcast(&physical_mb, 1, MPI_DOUBLE, 0, comm);
    if (physical_mb > 0 && !factor_fits_in_memory(out_of_core_mb, physical_mb / kInCoreShare))
        throw SolveError(out_of_memory_text(out_of_core_mb));
    return true;
}

bool factor_fits_in_memory(double estimate_mb, double allowed_mb) {
    return allowed_mb <= 0 || estimate_mb <= kInCoreShare * allowed_mb;
}

bool factor_out_of_core(Mat F) {
    MatSolverType package;
    COREMODAL_PETSC(MatFactorGetSolverType(F, &package));
    if (std::string(package) != MATSOLVERMUMPS) return false;
    PetscInt ooc = 0;
    COREMODAL_PETSC(MatMumpsGetIcntl(F, 22, &ooc));
    return ooc == 1;
}

PetscErrorCode factor_symmetric(Mat A, const char* package, PetscMatrix& F) {
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    COREMODAL_PETSC(MatGetFactor(A, package, MAT_FACTOR_CHOLESKY, F.out()));
    // ICNTL(13) = 1 keeps MUMPS's root front off ScaLAPACK, so MUMPS can
    // count negative pivots in parallel too; in one process it measured
    // faster as well (bench/results/log.md, issue 19).
    if (std::string(package) == MATSOLVERMUMPS) COREMODAL_PETSC(MatMumpsSetIcntl(F, 13, 1));
    PetscIndexSet row_perm, col_perm;
    COREMODAL_PETSC(MatGetOrdering(A, MATORDERINGNATURAL, row_perm.out(), col_perm.out()));
    MatFactorInfo info;
    COREMODAL_PETSC(MatFactorInfoInitialize(&info));
    COREMODAL_PETSC(MatCholeskyFactorSymbolic(F, A, row_perm, &info));
    if (std::string(package) == MATSOLVERMUMPS) out_of_core_if_too_large(F);
    return MatCholeskyFactorNumeric(F, A, &info);
}

PetscMatrix ldlt_factor(Mat A, const char* what) {
    PetscMatrix F;
    COREMODAL_PETSC(factor_symmetric(A, MATSOLVERMUMPS, F));
    MatFactorError factor_error;
    COREMODAL_PETSC(MatFactorGetError(F, &factor_error));
    if (factor_error != MAT_FACTOR_NOERROR)
        throw SolveError(std::string("the LDL^T factorisation of ") + what +
                         " failed (MUMPS error); the model may have a part that is not held");
    return F;
}

long negative_pivots(Mat F) {
    // Zero and positive counts would need MUMPS null-pivot detection
    // (ICNTL(24)); the negative count is all the checks need.
    PetscInt n_negative;
    COREMODAL_PETSC(MatGetInertia(F, &n_negative, nullptr, nullptr));
    return n_negative;
}

long negative_eigenvalue_count(Mat A, const char* what) { return negative_pivots(ldlt_factor(A, what)); }

PC direct_shift_and_invert(ST st) {
    KSP ksp;
    PC pc;
    COREMODAL_PETSC(STSetType(st, STSINVERT));
    COREMODAL_PETSC(STGetKSP(st, &ksp));
    COREMODAL_PETSC(KSPSetType(ksp, KSPPREONLY));
    COREMODAL_PETSC(KSPGetPC(ksp, &pc));
    return pc;
}

PetscKsp direct_cholesky_solver(MPI_Comm comm, const char* prefix) {
    PetscKsp ksp;
    COREMODAL_PETSC(KSPCreate(comm, ksp.out()));
    COREMODAL_PETSC(KSPSetType(ksp, KSPPREONLY));
    PC pc = nullptr;
    COREMODAL_PETSC(KSPGetPC(ksp, &pc));
    COREMODAL_PETSC(PCSetType(pc, PCCHOLESKY));
    COREMODAL_PETSC(PCFactorSetMatSolverType(pc, shift_invert_factor_package(comm)));
    COREMODAL_PETSC(KSPSetOptionsPrefix(ksp, prefix));
    COREMODAL_PETSC(KSPSetFromOptions(ksp));
    return ksp;
}

}  // namespace coremodal
