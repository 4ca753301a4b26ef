#include "eigensolve/zero_frequency_speeds.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "eigensolve/modal_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace coremodal {
namespace {

// A pencil eigenpair whose relative residual exceeds this is not accepted:
// the symmetric solver's own bound for reported modes (modal_solver.cpp).
constexpr double kMaxPencilResidual = 1e-8;
// Eigenvalues computed beyond those counted: they show the gap above the
// last one and catch a degenerate partner.
constexpr int kExtraEigenvalues = 4;
// Tries with more eigenvalues when fewer than counted converged.
constexpr int kMaxTries = 3;

using Eps = PetscHandle<EPS, EPSDestroy>;

// The rows' nonzero counts of the real form below (its columns 2j and 2j+1
// are owned where j is): each entry of P or Q in row i lands once in row
// 2i and once in row 2i+1.
struct Preallocation {
    std::vector<PetscInt> diagonal, off_diagonal;
};
Preallocation real_form_preallocation(Mat P, Mat Q, PetscInt lo, PetscInt hi) {
    Preallocation out{std::vector<PetscInt>(static_cast<size_t>(2 * (hi - lo)), 0), {}};
    out.off_diagonal = out.diagonal;
    for (Mat part : {P, Q}) {
        if (!part) continue;
        for (PetscInt i = lo; i < hi; ++i) {
            PetscInt nc = 0;
            const PetscInt* cols = nullptr;
            COREMODAL_PETSC(MatGetRow(part, i, &nc, &cols, nullptr));
            for (PetscInt c = 0; c < nc; ++c)
                for (int half = 0; half < 2; ++half)
                    ++(cols[c] >= lo && cols[c] < hi ? out.diagonal
                                                     : out.off_diagonal)[static_cast<size_t>(2 * (i - lo) + half)];
            COREMODAL_PETSC(MatRestoreRow(part, i, &nc, &cols, nullptr));
        }
    }
    return out;
}

// sign * part's local rows i into the rows 2i + row_half, columns 2j + col_half.
void put_block(Mat out, Mat part, double sign, int row_half, int col_half) {
    PetscInt lo = 0, hi = 0;
    COREMODAL_PETSC(MatGetOwnershipRange(part, &lo, &hi));
    for (PetscInt i = lo; i < hi; ++i) {
        PetscInt nc = 0;
        const PetscInt* cols = nullptr;
        const PetscScalar* vals = nullptr;
        COREMODAL_PETSC(MatGetRow(part, i, &nc, &cols, &vals));
        std::vector<PetscInt> c2(static_cast<size_t>(nc));
        std::vector<PetscScalar> v2(static_cast<size_t>(nc));
        for (PetscInt c = 0; c < nc; ++c) c2[c] = 2 * cols[c] + col_half, v2[c] = sign * vals[c];
        const PetscInt row = 2 * i + row_half;
        COREMODAL_PETSC(MatSetValues(out, 1, &row, nc, c2.data(), v2.data(), INSERT_VALUES));
        COREMODAL_PETSC(MatRestoreRow(part, i, &nc, &cols, &vals));
    }
}

// The real symmetric form of the Hermitian H = P + i Q (P symmetric, Q
// real skew, or none) on x = a + i b interleaved: H x = (P a - Q b) +
// i (Q a + P b), so the rows 2i and 2i+1 hold [P_ij, -Q_ij; Q_ij, P_ij] at
// the columns 2j, 2j+1. Rows of P and Q are read locally, so the form is
// distributed as P is (the rows of node pair i stay on the rank of row i).
PetscMatrix real_form(Mat P, Mat Q) {
    PetscInt n = 0, lo = 0, hi = 0;
    COREMODAL_PETSC(MatGetSize(P, &n, nullptr));
    COREMODAL_PETSC(MatGetOwnershipRange(P, &lo, &hi));
    const Preallocation nnz = real_form_preallocation(P, Q, lo, hi);
    PetscMatrix out;
    COREMODAL_PETSC(MatCreateAIJ(PetscObjectComm((PetscObject)P), 2 * (hi - lo), 2 * (hi - lo), 2 * n, 2 * n, 0,
                                 nnz.diagonal.data(), 0, nnz.off_diagonal.data(), out.out()));
    put_block(out, P, 1, 0, 0);
    put_block(out, P, 1, 1, 1);
    if (Q) {
        put_block(out, Q, -1, 0, 1);
        put_block(out, Q, 1, 1, 0);
    }
    COREMODAL_PETSC(MatAssemblyBegin(out, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(out, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatSetOption(out, MAT_SYMMETRIC, PETSC_TRUE));
    return out;
}

// A = -K_Omega + r^2 M: the real part of B_r (header).
PetscMatrix real_part_of_B(const OperatorSet& ops, double ratio) {
    PetscMatrix A;
    COREMODAL_PETSC(MatDuplicate(ops.M(), MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatScale(A, ratio * ratio));
    if (ops.has(Term::centrifugal))
        COREMODAL_PETSC(MatAXPY(A, -1.0, ops[Term::centrifugal], DIFFERENT_NONZERO_PATTERN));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    return A;
}

// The pencil's matrices: K (at rest, with any prestress of the set) and
// B = B_r, in the real form for r > 0; the 1-norms that scale the residuals.
struct Pencil {
    EffectiveStiffness stiffness;
    PetscMatrix K2;  // r > 0: diag(K, K)
    PetscMatrix B;
    int copies = 1;
    double norm_K = 0, norm_B = 0;

    Pencil(const OperatorSet& ops, double ratio) : stiffness(ops, 0.0) {
        PetscMatrix A = real_part_of_B(ops, ratio);
        if (ratio > 0) {
            // Im B_r = -r G_c: G_c scaled into a copy, the set's own left alone.
            PetscMatrix Q;
            if (ops.has(Term::gyroscopic)) {
                COREMODAL_PETSC(MatDuplicate(ops[Term::gyroscopic], MAT_COPY_VALUES, Q.out()));
                COREMODAL_PETSC(MatScale(Q, -ratio));
            }
            B = real_form(A, Q.get());
            K2 = real_form(stiffness.get(), nullptr);
            copies = 2;
        } else {
            B = std::move(A);
        }
        norm_K = norm_1(K());
        norm_B = norm_1(B);
    }
    Mat K() const { return K2.get() ? K2.get() : stiffness.get(); }
};

// neg(K + s K_Omega) = neg(K - s B).
long negative_count(const Pencil& p, double s, const char* what) {
    PetscMatrix A;
    COREMODAL_PETSC(MatDuplicate(p.K(), MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -s, p.B, DIFFERENT_NONZERO_PATTERN));
    return negative_eigenvalue_count(A, what);
}

// The count's premise: K positive definite, i.e. no eigenvalue of
// K x = lambda M x below the rigid line (a held structure).
void require_held(const OperatorSet& ops, const Pencil& p, double rigid_omega) {
    PetscMatrix A;
    COREMODAL_PETSC(MatDuplicate(p.stiffness.get(), MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -rigid_omega * rigid_omega, ops.M(), DIFFERENT_NONZERO_PATTERN));
    const long rigid = negative_eigenvalue_count(A, "K - omega_0^2 M");
    if (rigid > 0)
        throw SolveError("the speeds of zero rotating-frame frequency need a held structure (K positive definite), "
                         "but K has " + std::to_string(rigid) + " mode" + (rigid == 1 ? "" : "s") +
                         " below the rigid line (a free body): its rigid motions have zero frequency at every speed");
}

// B x = c K x, the largest c (c = 1/Omega^2), K factored once by Cholesky.
Eps configure(const Pencil& p, int nev, const SolveRequest& request) {
    Eps eps;
    COREMODAL_PETSC(EPSCreate(PetscObjectComm((PetscObject)p.K()), eps.out()));
    COREMODAL_PETSC(EPSSetOperators(eps, p.B, p.K()));
    COREMODAL_PETSC(EPSSetProblemType(eps, EPS_GHEP));
    COREMODAL_PETSC(EPSSetType(eps, EPSKRYLOVSCHUR));
    COREMODAL_PETSC(EPSSetWhichEigenpairs(eps, EPS_LARGEST_REAL));
    COREMODAL_PETSC(EPSSetDimensions(eps, nev, PETSC_DEFAULT, PETSC_DEFAULT));
    COREMODAL_PETSC(EPSSetTolerances(eps, request.tolerance, request.max_iterations));
    ST st;
    COREMODAL_PETSC(EPSGetST(eps, &st));
    COREMODAL_PETSC(STSetType(st, STSHIFT));  // operator K^-1 B: a solve with K, no shift
    KSP ksp;
    PC pc;
    COREMODAL_PETSC(STGetKSP(st, &ksp));
    COREMODAL_PETSC(KSPSetType(ksp, KSPPREONLY));
    COREMODAL_PETSC(KSPGetPC(ksp, &pc));
    COREMODAL_PETSC(PCSetType(pc, PCCHOLESKY));
    COREMODAL_PETSC(PCFactorSetMatSolverType(pc, shift_invert_factor_package(PetscObjectComm((PetscObject)p.K()))));
    COREMODAL_PETSC(EPSSetOptionsPrefix(eps, "pencil_"));  // -pencil_eps_*, -pencil_st_* for experts
    COREMODAL_PETSC(EPSSetFromOptions(eps));
    return eps;
}

double residual(const Pencil& p, double mu, Vec x) {
    PetscVector Kx, Bx;
    COREMODAL_PETSC(VecDuplicate(x, Kx.out()));
    COREMODAL_PETSC(VecDuplicate(x, Bx.out()));
    COREMODAL_PETSC(MatMult(p.K(), x, Kx));
    COREMODAL_PETSC(MatMult(p.B, x, Bx));
    COREMODAL_PETSC(VecAXPY(Kx, -mu, Bx));
    return vector_norm(Kx) / ((p.norm_K + mu * p.norm_B) * vector_norm(x));
}

// The real form's x_2 = (a_1, b_1, a_2, b_2, ...) as a and b, each laid
// out as K's rows (pair i on the rank of row i).
void split_interleaved(Vec x2, Mat K, ZeroFrequencySpeed& z) {
    COREMODAL_PETSC(MatCreateVecs(K, z.x.out(), nullptr));
    COREMODAL_PETSC(VecDuplicate(z.x, z.y.out()));
    const PetscScalar* in = nullptr;
    PetscScalar *a = nullptr, *b = nullptr;
    PetscInt n_local = 0;
    COREMODAL_PETSC(VecGetLocalSize(z.x, &n_local));
    COREMODAL_PETSC(VecGetArrayRead(x2, &in));
    COREMODAL_PETSC(VecGetArray(z.x, &a));
    COREMODAL_PETSC(VecGetArray(z.y, &b));
    for (PetscInt i = 0; i < n_local; ++i) a[i] = in[2 * i], b[i] = in[2 * i + 1];
    COREMODAL_PETSC(VecRestoreArray(z.y, &b));
    COREMODAL_PETSC(VecRestoreArray(z.x, &a));
    COREMODAL_PETSC(VecRestoreArrayRead(x2, &in));
}

// The converged pairs with Omega^2 = 1/c below max_spin^2, ascending in Omega.
std::vector<ZeroFrequencySpeed> below(EPS eps, const Pencil& p, double max_spin) {
    PetscInt n_converged = 0;
    COREMODAL_PETSC(EPSGetConverged(eps, &n_converged));
    std::vector<ZeroFrequencySpeed> out;
    for (PetscInt i = 0; i < n_converged; ++i) {
        PetscScalar c;
        COREMODAL_PETSC(EPSGetEigenvalue(eps, i, &c, nullptr));
        if (!(PetscRealPart(c) * max_spin * max_spin > 1)) continue;  // Omega^2 = 1/c >= max_spin^2, or c <= 0
        ZeroFrequencySpeed z;
        z.spin = 1 / std::sqrt(PetscRealPart(c));
        PetscVector x;
        COREMODAL_PETSC(MatCreateVecs(p.K(), x.out(), nullptr));
        COREMODAL_PETSC(EPSGetEigenvector(eps, i, x, nullptr));
        z.relative_residual = residual(p, z.spin * z.spin, x);
        if (p.copies == 2)
            split_interleaved(x, p.stiffness.get(), z);
        else
            z.x = std::move(x);
        out.push_back(std::move(z));
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.spin < b.spin; });
    return out;
}

// What the speeds are, for the errors.
std::string speeds_name(double ratio) {
    return ratio == 0 ? "speeds of zero rotating-frame frequency"
                      : "speeds where a mode's rotating-frame frequency is " + significant(ratio, 6) + " f_rot";
}

std::string mismatch_text(double ratio, long counted, size_t found, double max_spin) {
    std::ostringstream s;
    s << "the inertia of K - Omega^2 B_r (r = " << ratio << ") at " << max_spin * 30 / M_PI << " rpm counts "
      << counted << " " << speeds_name(ratio) << " below it (real form: each twice for r > 0), but the pencil's "
      << "solver found " << found << ": raise [analysis] max_iterations";
    return s.str();
}

}  // namespace

ZeroFrequencySpeeds frequency_ratio_speeds(const OperatorSet& ops, double ratio, double max_spin, double rigid_omega,
                                           const SolveRequest& request) {
    COREMODAL_ASSERT(ratio >= 0);
    ZeroFrequencySpeeds out;
    out.max_spin = max_spin;
    out.ratio = ratio;
    // r = 0 without the term: K does not change with speed, nothing to find.
    if ((ratio == 0 && !ops.has(Term::centrifugal)) || max_spin <= 0) return out;
    const Pencil pencil(ops, ratio);
    out.copies = pencil.copies;
    require_held(ops, pencil, rigid_omega);
    out.counted = negative_count(pencil, max_spin * max_spin, "K - Omega^2 B_r at the sweep's last speed");
    // The real form's inertia is twice the complex one (x and i x): an odd count is a broken factor.
    COREMODAL_ASSERT(out.counted % out.copies == 0);
    if (out.counted == 0) return out;
    for (int attempt = 0; attempt < kMaxTries; ++attempt) {
        const int nev = static_cast<int>(out.counted) + kExtraEigenvalues * out.copies * (1 << attempt);
        const Eps eps = configure(pencil, nev, request);
        COREMODAL_PETSC(EPSSolve(eps));
        out.speeds = below(eps, pencil, max_spin);
        if (static_cast<long>(out.speeds.size()) == out.counted) break;
    }
    if (static_cast<long>(out.speeds.size()) != out.counted)
        throw SolveError(mismatch_text(ratio, out.counted, out.speeds.size(), max_spin));
    for (const ZeroFrequencySpeed& z : out.speeds)
        if (z.relative_residual > kMaxPencilResidual)
            throw SolveError("of the " + speeds_name(ratio) + ", the one at " + std::to_string(z.spin * 30 / M_PI) +
                             " rpm has a relative residual of " + std::to_string(z.relative_residual) +
                             " (above 1e-8): raise [analysis] max_iterations");
    return out;
}

ZeroFrequencySpeeds zero_frequency_speeds(const OperatorSet& ops, double max_spin, double rigid_omega,
                                          const SolveRequest& request) {
    return frequency_ratio_speeds(ops, 0.0, max_spin, rigid_omega, request);
}

}  // namespace coremodal
