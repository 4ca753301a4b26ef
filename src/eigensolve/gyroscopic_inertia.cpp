#include "eigensolve/gyroscopic_inertia.hpp"

#include "common/error.hpp"
#include "common/log_event.hpp"
#include "eigensolve/petsc_algebra.hpp"

#include <petscmat.h>

#include <string>
#include <vector>

namespace coremodal {
namespace {

// Blocks of one assembled matrix that should be equal (or zero) are accepted
// as such when they differ by this fraction of their 1-norm (header).
constexpr double kMirrorTolerance = 1e-13;

PetscMatrix sub_matrix(Mat A, IS rows, IS cols) {
    PetscMatrix out;
    COREMODAL_PETSC(MatCreateSubMatrix(A, rows, cols, MAT_INITIAL_MATRIX, out.out()));
    return out;
}

// ||a + sign b||_1 <= kMirrorTolerance (||a||_1 + ||b||_1).
bool nearly(Mat a, Mat b, double sign) {
    PetscMatrix d;
    COREMODAL_PETSC(MatDuplicate(a, MAT_COPY_VALUES, d.out()));
    COREMODAL_PETSC(MatAXPY(d, sign, b, DIFFERENT_NONZERO_PATTERN));
    return norm_1(d) <= kMirrorTolerance * (norm_1(a) + norm_1(b));
}

bool nearly_zero(Mat a, double scale) { return norm_1(a) <= kMirrorTolerance * scale; }

// A symmetric term [[S, 0], [0, S]] on the families: S (the mean of the two diagonal blocks), or none.
std::optional<PetscMatrix> mirrored_block(Mat A, IS first, IS second) {
    PetscMatrix s11 = sub_matrix(A, first, first), s22 = sub_matrix(A, second, second);
    const double scale = norm_1(A);
    if (!nearly(s11, s22, -1.0) || !nearly_zero(sub_matrix(A, first, second), scale) ||
        !nearly_zero(sub_matrix(A, second, first), scale))
        return std::nullopt;
    COREMODAL_PETSC(MatAXPY(s11, 1.0, s22, DIFFERENT_NONZERO_PATTERN));
    COREMODAL_PETSC(MatScale(s11, 0.5));
    return s11;
}

// G = [[0, Gab], [-Gab, 0]] with Gab symmetric: Gab (symmetrised), or none.
std::optional<PetscMatrix> mirrored_coupling(Mat G, IS first, IS second) {
    PetscMatrix g12 = sub_matrix(G, first, second), g21 = sub_matrix(G, second, first), g12t;
    const double scale = norm_1(G);
    COREMODAL_PETSC(MatTranspose(g12, MAT_INITIAL_MATRIX, g12t.out()));
    if (!nearly_zero(sub_matrix(G, first, first), scale) || !nearly_zero(sub_matrix(G, second, second), scale) ||
        !nearly(g12, g21, +1.0) || !nearly(g12, g12t, -1.0))
        return std::nullopt;
    COREMODAL_PETSC(MatAXPY(g12, 1.0, g12t, DIFFERENT_NONZERO_PATTERN));
    COREMODAL_PETSC(MatScale(g12, 0.5));
    return g12;
}

PetscInt size_of(IS is) {
    PetscInt n;
    COREMODAL_PETSC(ISGetSize(is, &n));
    return n;
}

// Split families (header, 3): every symmetric term has zero blocks between
// the two sets and G only those; then S G with S = -1 on the first set, +1
// on the second (symmetric), or none.
std::optional<PetscMatrix> split_coupling(const std::vector<Mat>& symmetric, Mat G, IS first, IS second) {
    for (Mat A : symmetric)
        if (A && !nearly_zero(sub_matrix(A, first, second), norm_1(A))) return std::nullopt;
    const double scale = norm_1(G);
    if (!nearly_zero(sub_matrix(G, first, first), scale) || !nearly_zero(sub_matrix(G, second, second), scale))
        return std::nullopt;
    PetscMatrix out;
    COREMODAL_PETSC(MatDuplicate(G, MAT_COPY_VALUES, out.out()));
    PetscVector s;
    COREMODAL_PETSC(MatCreateVecs(G, nullptr, s.out()));
    COREMODAL_PETSC(VecSet(s, 1.0));
    PetscInt n;
    const PetscInt* rows;
    COREMODAL_PETSC(ISGetLocalSize(first, &n));
    COREMODAL_PETSC(ISGetIndices(first, &rows));
    for (PetscInt k = 0; k < n; ++k) COREMODAL_PETSC(VecSetValue(s, rows[k], -1.0, INSERT_VALUES));
    COREMODAL_PETSC(ISRestoreIndices(first, &rows));
    COREMODAL_PETSC(VecAssemblyBegin(s));
    COREMODAL_PETSC(VecAssemblyEnd(s));
    COREMODAL_PETSC(MatDiagonalScale(out, s, nullptr));
    return out;
}

// [[A, B], [C, D]] as one AIJ matrix (null blocks are zero).
PetscMatrix blocks(Mat a, Mat b, Mat c, Mat d) {
    PetscMatrix nest, out;
    Mat m[4] = {a, b, c, d};
    const MPI_Comm comm = PetscObjectComm((PetscObject)(a ? a : b));
    COREMODAL_PETSC(MatCreateNest(comm, 2, nullptr, 2, nullptr, m, nest.out()));
    COREMODAL_PETSC(MatConvert(nest, MATAIJ, MAT_INITIAL_MATRIX, out.out()));
    return out;
}

PetscMatrix negated(Mat A) {
    PetscMatrix out;
    COREMODAL_PETSC(MatDuplicate(A, MAT_COPY_VALUES, out.out()));
    COREMODAL_PETSC(MatScale(out, -1.0));
    return out;
}

}  // namespace

// The counted matrix is  base + spin^2 centrifugal - omega^2 mass + sign omega spin coupling,
// for each sign in `signs`; every part on one nonzero pattern (header, 2).
struct GyroscopicInertia::Pattern {
    bool mirrored = false;
    bool real_form = false;  // counted on [[A, -B], [B, A]]: every eigenvalue twice
    bool split = false;      // split families (header, 3)
    PetscMatrix base, centrifugal, mass, coupling;  // centrifugal may be null
    PetscMatrix work, factor;
    bool analysed = false;
    std::vector<double> signs;  // mirrored: {+1, -1}; the real form: {+1}, counted twice

    // Puts every part on the union of their patterns (a copy per part with
    // explicit zeros). `all` holds the union only for its pattern (MatAXPY
    // with a zero factor would return at once, leaving the pattern as it is).
    void unify() {
        PetscMatrix all;
        COREMODAL_PETSC(MatDuplicate(base, MAT_COPY_VALUES, all.out()));
        for (Mat p : {centrifugal.get(), mass.get(), coupling.get()})
            if (p) COREMODAL_PETSC(MatAXPY(all, 1.0, p, DIFFERENT_NONZERO_PATTERN));
        for (PetscMatrix* p : {&base, &centrifugal, &mass, &coupling}) {
            if (!p->get()) continue;
            PetscMatrix u;
            COREMODAL_PETSC(MatDuplicate(all, MAT_DO_NOT_COPY_VALUES, u.out()));
            COREMODAL_PETSC(MatZeroEntries(u));
            COREMODAL_PETSC(MatAXPY(u, 1.0, *p, SUBSET_NONZERO_PATTERN));
            *p = std::move(u);
        }
        COREMODAL_PETSC(MatDuplicate(all, MAT_DO_NOT_COPY_VALUES, work.out()));
        COREMODAL_PETSC(MatSetOption(work, MAT_SYMMETRIC, PETSC_TRUE));
    }

    long negative_pivots() {
        MatFactorInfo info;
        COREMODAL_PETSC(MatFactorInfoInitialize(&info));
        if (!analysed) {
            COREMODAL_PETSC(MatGetFactor(work, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, factor.out()));
            COREMODAL_PETSC(MatMumpsSetIcntl(factor, 13, 1));  // as negative_eigenvalue_count
            PetscIndexSet row_perm, col_perm;
            COREMODAL_PETSC(MatGetOrdering(work, MATORDERINGNATURAL, row_perm.out(), col_perm.out()));
            COREMODAL_PETSC(MatCholeskyFactorSymbolic(factor, work, row_perm, &info));
            analysed = true;
        }
        COREMODAL_PETSC(MatCholeskyFactorNumeric(factor, work, &info));
        MatFactorError error;
        COREMODAL_PETSC(MatFactorGetError(factor, &error));
        if (error != MAT_FACTOR_NOERROR)
            throw SolveError("the LDL^T factorisation of Q(omega) failed (MUMPS error); the model may have a part "
                             "that is not held");
        PetscInt n_negative;
        COREMODAL_PETSC(MatGetInertia(factor, &n_negative, nullptr, nullptr));
        return n_negative;
    }
};

GyroscopicInertia::~GyroscopicInertia() = default;

GyroscopicInertia::GyroscopicInertia(const OperatorSet& ops, IS first, IS second) : pattern_(std::make_unique<Pattern>()) {
    Pattern& p = *pattern_;
    COREMODAL_ASSERT(ops.has(Term::gyroscopic));
    const EffectiveStiffness at_rest(ops, 0.0);  // K + K_sigma
    const Mat centrifugal = ops.has(Term::centrifugal) ? ops[Term::centrifugal] : nullptr;
    if (first && second && size_of(first) == size_of(second)) {
        std::optional<PetscMatrix> base = mirrored_block(at_rest.get(), first, second);
        std::optional<PetscMatrix> mass = mirrored_block(ops.M(), first, second);
        std::optional<PetscMatrix> cent;
        if (centrifugal)
            cent = mirrored_block(centrifugal, first, second);
        else
            cent.emplace();  // no term: nothing to mirror
        std::optional<PetscMatrix> coupling = mirrored_coupling(ops[Term::gyroscopic], first, second);
        if (base && mass && cent && coupling) {
            p.mirrored = true;
            p.base = std::move(*base);
            p.mass = std::move(*mass);
            p.centrifugal = std::move(*cent);
            p.coupling = std::move(*coupling);
            p.signs = {+1.0, -1.0};
        }
    }
    if (!p.mirrored && first && second) {
        if (std::optional<PetscMatrix> coupling =
                split_coupling({at_rest.get(), ops.M(), centrifugal}, ops[Term::gyroscopic], first, second)) {
            p.split = true;
            COREMODAL_PETSC(MatDuplicate(at_rest.get(), MAT_COPY_VALUES, p.base.out()));
            COREMODAL_PETSC(MatDuplicate(ops.M(), MAT_COPY_VALUES, p.mass.out()));
            if (centrifugal) COREMODAL_PETSC(MatDuplicate(centrifugal, MAT_COPY_VALUES, p.centrifugal.out()));
            p.coupling = std::move(*coupling);
            p.signs = {+1.0};
        }
    }
    if (!p.mirrored && !p.split) {  // the real form [[A, -B], [B, A]] of Q = A + iB
        p.real_form = true;
        p.base = blocks(at_rest.get(), nullptr, nullptr, at_rest.get());
        p.mass = blocks(ops.M(), nullptr, nullptr, ops.M());
        if (centrifugal) p.centrifugal = blocks(centrifugal, nullptr, nullptr, centrifugal);
        const PetscMatrix minus_g = negated(ops[Term::gyroscopic]);
        p.coupling = blocks(nullptr, minus_g, ops[Term::gyroscopic], nullptr);
        p.signs = {+1.0};
    }
    p.unify();
}

long GyroscopicInertia::negative_count(double spin, double spin_squared, double omega) {
    return negative_count(Combination{1.0, spin_squared, -omega * omega, omega * spin});
}

long GyroscopicInertia::negative_count(const Combination& c) {
    const LogEvent event("CmInertiaCount");
    Pattern& p = *pattern_;
    // Without the coupling the two mirrored families are one matrix twice.
    const bool twice = p.mirrored && c.coupling == 0;
    long count = 0;
    for (double sign : p.signs) {
        if (twice && sign < 0) {
            count *= 2;
            break;
        }
        COREMODAL_PETSC(MatCopy(p.base, p.work, SAME_NONZERO_PATTERN));
        COREMODAL_PETSC(MatScale(p.work, c.stiffness));
        if (p.centrifugal.get()) COREMODAL_PETSC(MatAXPY(p.work, c.centrifugal, p.centrifugal, SAME_NONZERO_PATTERN));
        COREMODAL_PETSC(MatAXPY(p.work, c.mass, p.mass, SAME_NONZERO_PATTERN));
        COREMODAL_PETSC(MatAXPY(p.work, sign * c.coupling, p.coupling, SAME_NONZERO_PATTERN));
        count += p.negative_pivots();
    }
    return p.real_form ? count / 2 : count;  // the real form has every eigenvalue of Q twice
}

bool GyroscopicInertia::uses_mirrored_families() const { return pattern_->mirrored; }

bool GyroscopicInertia::uses_split_families() const { return pattern_->split; }

GyroscopicInertia::FamilyBlocks GyroscopicInertia::family_blocks() const {
    const Pattern& p = *pattern_;
    if (!p.mirrored) return {};
    return {p.base.get(), p.centrifugal.get(), p.mass.get(), p.coupling.get()};
}

}  // namespace coremodal
