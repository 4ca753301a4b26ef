// Y = A X for a sparse A in one process (SeqAIJ) and a block X of columns:
// block Lanczos's products with M, one per pass. PETSc's MatMatMult for
// AIJ times dense goes column by column through A's entries; here each
// entry of A multiplies a row of the block held contiguously (the block is
// transposed in and out), so an entry is read once for all the columns and
// the columns' multiply-adds run in vector registers: case 03's M (181,152
// rows) times 16 columns in 0.11-0.13 s against 0.20-0.24 s
// (bench/results/log.md, session 16). In parallel PETSc's product stays.
#pragma once

#include <petscmat.h>

#include <vector>

namespace coremodal {

class SparseBlockProduct {
public:
    // Whether A is a one-process AIJ matrix this product handles.
    static bool handles(Mat A);

    // out = A in, `cols` columns of A's rows each (column-major, leading
    // dimension the row count).
    void operator()(Mat A, int cols, const double* in, double* out);

private:
    std::vector<double> rows_in_, rows_out_;  // the block row-major, kept between passes
};

}  // namespace coremodal
