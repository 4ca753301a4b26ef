#include "eigensolve/single_factor.hpp"

#include "eigensolve/petsc_algebra.hpp"

#include "common/error.hpp"

#include <smumps_c.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace coremodal {

// MUMPS's instance, kept out of the header (smumps_c.h is only needed here).
struct SingleLdlt::Mumps {
    SMUMPS_STRUC_C id{};
    std::vector<MUMPS_INT> rows, cols;
    std::vector<float> values;
    void run(int job) {
        id.job = job;
        smumps_c(&id);
    }
    // Fortran's 1-based ICNTL(i), INFOG(i).
    MUMPS_INT& icntl(int i) { return id.icntl[i - 1]; }
    MUMPS_INT infog(int i) const { return id.infog[i - 1]; }
};

namespace {

// MUMPS's status after a step: INFOG(1) < 0 is an error (users' guide,
// section 8); -10: the matrix is singular in the working precision.
std::string mumps_failure_text(int infog1, int infog2) {
    return "the single-precision LDL^T factor of K - sigma M failed (SMUMPS INFOG(1) = " + std::to_string(infog1) +
           ", INFOG(2) = " + std::to_string(infog2) + ")";
}

// ||b - A x||_2 / (||A||_1 ||x||_2 + ||b||_2) for one column: the normwise
// backward error (Rigal and Gaches, Numer. Math. 1967; Higham, Accuracy and
// Stability of Numerical Algorithms, 2nd ed., SIAM 2002, Theorem 7.1).
double backward_error(PetscInt n, const double* r, const double* x, const double* b, double norm_1) {
    double rr = 0, xx = 0, bb = 0;
    for (PetscInt i = 0; i < n; ++i) {
        rr += r[i] * r[i];
        xx += x[i] * x[i];
        bb += b[i] * b[i];
    }
    const double denominator = norm_1 * std::sqrt(xx) + std::sqrt(bb);
    return denominator > 0 ? std::sqrt(rr) / denominator : 0.0;
}

}  // namespace

FactorPrecision factor_precision_choice(MPI_Comm comm) {
    char text[64] = "auto";
    PetscBool given = PETSC_FALSE;
    COREMODAL_PETSC(PetscOptionsGetString(nullptr, nullptr, "-factor_precision", text, sizeof text, &given));
    const std::string choice = text;
    if (choice != "auto" && choice != "single" && choice != "double")
        throw InputError("-factor_precision " + choice + ": expected single, double or auto");
    if (choice == "double") return {false, choice, "double precision, as -factor_precision double asks"};
    if (choice == "auto")
        return {false, choice,
                "double precision: the single-precision factor measured no faster on case 03 (its refined "
                "passes and Rayleigh-Ritz cleanup read its factor 32 times against the double's 14; "
                "bench/results/log.md), -factor_precision single to use it"};
    if (mpi_size(comm) > 1)
        return {false, choice,
                "double precision: the single-precision factor runs in one process only "
                "(-factor_precision single ignored)"};
    return {true, choice, "single precision refined in double, as -factor_precision single asks"};
}

SingleLdlt::SingleLdlt(Mat A) : mumps_(std::make_unique<Mumps>()), A_(A) {
    COREMODAL_ASSERT(SparseBlockProduct::handles(A));
    // Kept for the refinement's residuals, however the caller holds it.
    COREMODAL_PETSC(PetscObjectReference((PetscObject)A));
    COREMODAL_PETSC(MatGetSize(A, &n_, nullptr));
    PetscReal norm = 0;
    COREMODAL_PETSC(MatNorm(A, NORM_1, &norm));
    norm_1_ = norm;
    // The upper triangle (MUMPS sums both triangles' entries when given),
    // 1-based, in float.
    Mumps& m = *mumps_;
    const PetscInt *ia = nullptr, *ja = nullptr;
    PetscInt rows = 0;
    PetscBool done = PETSC_FALSE;
    COREMODAL_PETSC(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &rows, &ia, &ja, &done));
    const PetscScalar* a = nullptr;
    COREMODAL_PETSC(MatSeqAIJGetArrayRead(A, &a));
    for (PetscInt i = 0; i < rows; ++i)
        for (PetscInt p = ia[i]; p < ia[i + 1]; ++p)
            if (ja[p] >= i) {
                m.rows.push_back(MUMPS_INT(i + 1));
                m.cols.push_back(MUMPS_INT(ja[p] + 1));
                m.values.push_back(float(a[p]));
            }
    COREMODAL_PETSC(MatSeqAIJRestoreArrayRead(A, &a));
    COREMODAL_PETSC(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &rows, &ia, &ja, &done));

    m.id.comm_fortran = MUMPS_INT(MPI_Comm_c2f(PETSC_COMM_SELF));
    m.id.par = 1;
    m.id.sym = 2;  // symmetric, not necessarily definite: LDL^T with pivoting
    m.run(-1);
    // Quiet, as PETSc runs the double factor.
    m.icntl(1) = m.icntl(2) = m.icntl(3) = -1;
    m.icntl(4) = 0;
    // As the double factor (petsc_algebra.cpp): the root front like the
    // others, which also keeps the count in INFOG(12) exact.
    m.icntl(13) = 1;
    m.id.n = MUMPS_INT(n_);
    m.id.nnz = MUMPS_INT8(m.values.size());
    m.id.irn = m.rows.data();
    m.id.jcn = m.cols.data();
    m.id.a = m.values.data();
    m.run(1);
    if (m.infog(1) < 0) throw SolveError(mumps_failure_text(m.infog(1), m.infog(2)));
    if (factor_goes_out_of_core(PETSC_COMM_SELF, double(m.infog(17)), double(m.infog(27)))) m.icntl(22) = 1;
    m.run(2);
    if (m.infog(1) < 0) throw SolveError(mumps_failure_text(m.infog(1), m.infog(2)));
}

SingleLdlt::~SingleLdlt() {
    mumps_->run(-2);
    MatDestroy(&A_);
}

long SingleLdlt::negative_pivots() const { return mumps_->infog(12); }
bool SingleLdlt::out_of_core() const { return mumps_->id.icntl[21] == 1; }
long SingleLdlt::estimate_mb() const { return mumps_->infog(17); }

void SingleLdlt::solve(int cols, const double* in, double* out, double target) {
    const size_t size = size_t(n_) * size_t(cols);
    rhs_.resize(size);
    residual_.assign(in, in + size);
    product_out_.resize(size);
    std::fill(out, out + size, 0.0);
    Mumps& m = *mumps_;
    m.icntl(20) = 0;  // dense right-hand sides
    m.icntl(21) = 0;  // the solution overwrites them
    double previous = 0;
    for (int step = 1;; ++step) {
        // The correction through the single factor: each residual column
        // scaled to unit maximum first, so that float neither under- nor
        // overflows however small the residual has become.
        std::vector<double> scale(cols, 1.0);
        for (int c = 0; c < cols; ++c) {
            const double* r = residual_.data() + size_t(c) * n_;
            double largest = 0;
            for (PetscInt i = 0; i < n_; ++i) largest = std::max(largest, std::abs(r[i]));
            if (largest > 0) scale[c] = largest;
            for (PetscInt i = 0; i < n_; ++i) rhs_[size_t(c) * n_ + i] = float(r[i] / scale[c]);
        }
        m.id.nrhs = cols;
        m.id.lrhs = MUMPS_INT(n_);
        m.id.rhs = rhs_.data();
        m.run(3);
        ++factor_passes_;
        if (m.infog(1) < 0) throw SolveError(mumps_failure_text(m.infog(1), m.infog(2)));
        for (int c = 0; c < cols; ++c)
            for (PetscInt i = 0; i < n_; ++i) out[size_t(c) * n_ + i] += scale[c] * double(rhs_[size_t(c) * n_ + i]);
        // The residual in double: b - A x.
        product_(A_, cols, out, product_out_.data());
        double worst = 0;
        for (int c = 0; c < cols; ++c) {
            const size_t o = size_t(c) * n_;
            for (PetscInt i = 0; i < n_; ++i) residual_[o + i] = in[o + i] - product_out_[o + i];
            worst = std::max(worst, backward_error(n_, residual_.data() + o, out + o, in + o, norm_1_));
        }
        if (step == 1) first_error_ = std::max(first_error_, worst);
        if (worst <= target) {
            most_steps_ = std::max(most_steps_, step);
            ++solves_;
            return;
        }
        // Each step should gain a factor cond(A) u_single < 1; one that
        // does not halve the error has stalled.
        if (step >= kMaxRefinementSteps || (step > 1 && worst > 0.5 * previous))
            throw RefinementStalled("the single-precision solve's refinement stalled at a backward error of " +
                                    std::to_string(worst) + " after " + std::to_string(step) + " corrections (wanted " +
                                    std::to_string(target) + ")");
        previous = worst;
    }
}

double count_margin(const SingleLdlt& F) { return kBackwardErrorMargin * F.factor_backward_error() * F.norm_1(); }

bool single_count_proven(const SingleLdlt& F, Mat M, double sigma, const std::vector<double>& lambdas,
                         const std::vector<PetscVector>& vectors) {
    const double margin = count_margin(F);
    for (size_t i = 0; i < lambdas.size() && i < vectors.size(); ++i) {
        const double rho = quadratic_form(M, vectors[i]) / std::pow(vector_norm(vectors[i]), 2);
        if (std::abs(lambdas[i] - sigma) * rho <= margin) return false;
    }
    return !lambdas.empty();
}

}  // namespace coremodal
