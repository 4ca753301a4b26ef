#include "eigensolve/sparse_block_product.hpp"

#include "common/error.hpp"
#include "common/petsc_handle.hpp"

#include <cstring>

namespace coremodal {
namespace {

// W columns at a time: the accumulator is a fixed-size array the compiler
// keeps in vector registers.
template <int W>
inline __attribute__((always_inline)) void rows_times_columns(PetscInt n, const PetscInt* ia, const PetscInt* ja,
                                                              const double* a, const double* x, int ldx, double* y,
                                                              int ldy) {
    for (PetscInt i = 0; i < n; ++i) {
        double acc[W] = {};
        for (PetscInt p = ia[i]; p < ia[i + 1]; ++p) {
            const double value = a[p];
            const double* row = x + size_t(ja[p]) * size_t(ldx);
            for (int c = 0; c < W; ++c) acc[c] += value * row[c];
        }
        std::memcpy(y + size_t(i) * size_t(ldy), acc, sizeof acc);
    }
}

// `width` (16, 8, 4 or 1) columns; AVX2 where the CPU has it (target_clones
// on a plain function: clang does not clone templates).
__attribute__((target_clones("avx2", "default"))) void rows_times_block(int width, PetscInt n, const PetscInt* ia,
                                                                         const PetscInt* ja, const double* a,
                                                                         const double* x, int ldx, double* y,
                                                                         int ldy) {
    switch (width) {
        case 16: rows_times_columns<16>(n, ia, ja, a, x, ldx, y, ldy); break;
        case 8: rows_times_columns<8>(n, ia, ja, a, x, ldx, y, ldy); break;
        case 4: rows_times_columns<4>(n, ia, ja, a, x, ldx, y, ldy); break;
        default: rows_times_columns<1>(n, ia, ja, a, x, ldx, y, ldy); break;
    }
}

// The products' time in -log_view, beside PETSc's own MatMatMult.
PetscLogEvent product_event() {
    static const PetscLogEvent event = [] {
        PetscLogEvent e;
        PetscLogEventRegister("SparseBlockMult", MAT_CLASSID, &e);
        return e;
    }();
    return event;
}

}  // namespace

bool SparseBlockProduct::handles(Mat A) {
    PetscBool seqaij = PETSC_FALSE;
    COREMODAL_PETSC(PetscObjectTypeCompare((PetscObject)A, MATSEQAIJ, &seqaij));
    return seqaij;
}

void SparseBlockProduct::operator()(Mat A, int cols, const double* in, double* out) {
    PetscLogEventBegin(product_event(), A, 0, 0, 0);
    PetscInt n = 0;
    COREMODAL_PETSC(MatGetLocalSize(A, &n, nullptr));
    rows_in_.resize(size_t(n) * size_t(cols));
    rows_out_.resize(size_t(n) * size_t(cols));
    for (int c = 0; c < cols; ++c)
        for (PetscInt i = 0; i < n; ++i) rows_in_[size_t(i) * cols + c] = in[size_t(c) * n + i];
    const PetscInt *ia = nullptr, *ja = nullptr;
    PetscInt rows = 0;
    PetscBool done = PETSC_FALSE;
    COREMODAL_PETSC(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &rows, &ia, &ja, &done));
    COREMODAL_ASSERT(done && rows == n);
    const PetscScalar* a = nullptr;
    COREMODAL_PETSC(MatSeqAIJGetArrayRead(A, &a));
    // Columns in chunks of 16, 8, 4 and 1 (a block of 13: 8 + 4 + 1).
    for (int c = 0; c < cols;) {
        const double* x = rows_in_.data() + c;
        double* y = rows_out_.data() + c;
        const int left = cols - c;
        const int width = left >= 16 ? 16 : left >= 8 ? 8 : left >= 4 ? 4 : 1;
        rows_times_block(width, n, ia, ja, a, x, cols, y, cols);
        c += width;
    }
    COREMODAL_PETSC(MatSeqAIJRestoreArrayRead(A, &a));
    COREMODAL_PETSC(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &rows, &ia, &ja, &done));
    for (int c = 0; c < cols; ++c)
        for (PetscInt i = 0; i < n; ++i) out[size_t(c) * n + i] = rows_out_[size_t(i) * cols + c];
    PetscLogEventEnd(product_event(), A, 0, 0, 0);
}

}  // namespace coremodal
