#include "eigensolve/block_lanczos.hpp"

#include "eigensolve/sparse_block_product.hpp"

#include "common/error.hpp"

#include <Eigen/Dense>
#include <petscblaslapack.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>

namespace coremodal {
namespace {

// Rows of the basis multiplied at a time in the in-place products.
constexpr PetscInt kPanelRows = 4096;

// A block's direction whose part M-orthogonal to the basis is below this
// fraction of its length lies in the basis to round-off (the Krylov space
// has become invariant, as on a model with few modes): it is replaced by a
// fresh random direction instead of being normalised from noise.
constexpr double kDeflation = 1e-12;

// Columns of length n stored one after another (column-major, leading
// dimension n): the basis V and its M-images.
class Columns {
public:
    Columns(PetscInt n, int count) : n_(n), data_(size_t(n) * size_t(count)) {}
    double* col(int j) { return data_.data() + size_t(n_) * size_t(j); }

private:
    PetscInt n_;
    std::vector<double> data_;
};

// C (ldc) = alpha op(A) op(B) + beta C, through the BLAS PETSc links (the
// tall products here: a block against the whole basis).
void gemm(const char* ta, const char* tb, int m, int n, int k, double alpha, const double* A, PetscInt lda,
          const double* B, PetscInt ldb, double beta, double* C, PetscInt ldc) {
    PetscBLASInt bm = m, bn = n, bk = k, blda = PetscBLASInt(lda), bldb = PetscBLASInt(ldb), bldc = PetscBLASInt(ldc);
    if (m == 0 || n == 0) return;
    BLASgemm_(ta, tb, &bm, &bn, &bk, &alpha, A, &blda, B, &bldb, &beta, C, &bldc);
}

// The sum over the processes of each one's part of an inner product (the
// basis's rows are split like M's): every process then holds the same small
// matrix and takes the same steps on it.
void sum_over_processes(MPI_Comm comm, double* values, int count) {
    if (mpi_size(comm) > 1 && count > 0)
        MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, comm);
}

// `cols` columns of this process's n rows, as a dense matrix distributed
// like M's rows.
PetscMatrix dense_view(Mat M, PetscInt n, int cols, double* data) {
    PetscMatrix A;
    COREMODAL_PETSC(
        MatCreateDense(PetscObjectComm((PetscObject)M), n, PETSC_DECIDE, PETSC_DETERMINE, cols, data, A.out()));
    return A;
}

// out = M in, for `cols` columns (one pass over M for the block), by
// PETSc's product (in parallel).
void multiply(Mat M, PetscInt n, int cols, double* in, double* out) {
    PetscMatrix X = dense_view(M, n, cols, in), Y;
    COREMODAL_PETSC(MatMatMult(M, X, MAT_INITIAL_MATRIX, PETSC_DEFAULT, Y.out()));
    const double* y = nullptr;
    COREMODAL_PETSC(MatDenseGetArrayRead(Y, &y));
    std::memcpy(out, y, sizeof(double) * size_t(n) * size_t(cols));
    COREMODAL_PETSC(MatDenseRestoreArrayRead(Y, &y));
}

// out = (K - sigma M)^-1 in, for `cols` columns: one pass over PETSc's
// factor F.
BlockSolve factor_solve(Mat F, Mat M, PetscInt n) {
    return [F, M, n](int cols, const double* in, double* out) {
        PetscMatrix B = dense_view(M, n, cols, const_cast<double*>(in)), X = dense_view(M, n, cols, out);
        COREMODAL_PETSC(MatMatSolve(F, B, X));
    };
}

// The dense algebra's time in -log_view and in `coremodal converge`'s
// breakdown (analyses/converge/model_ladder.cpp), beside the solves'
// MatMatSolve and the products' MatMatMult.
PetscLogEvent orthogonalization_event() {
    static const PetscLogEvent event = [] {
        PetscClassId id;
        PetscLogEvent e;
        PetscClassIdRegister("Block Lanczos", &id);
        PetscLogEventRegister("BlockOrthogonal", id, &e);
        return e;
    }();
    return event;
}

// Logs the enclosing scope as orthogonalization.
struct OrthogonalizationScope {
    OrthogonalizationScope() { PetscLogEventBegin(orthogonalization_event(), 0, 0, 0, 0); }
    ~OrthogonalizationScope() { PetscLogEventEnd(orthogonalization_event(), 0, 0, 0, 0); }
};

class BlockLanczos {
public:
    // n: the rows of the basis this process holds (M's local rows).
    BlockLanczos(BlockSolve solve, Mat M, PetscInt n, int block, int capacity)
        : solve_(std::move(solve)), M_(M), comm_(PetscObjectComm((PetscObject)M)), n_(n), b_(block), cap_(capacity),
          V_(n, capacity + block), MV_(n, capacity + block),
          panel_(std::size_t(std::min<PetscInt>(n, kPanelRows)) * std::size_t(capacity + block)),
          H_(Eigen::MatrixXd::Zero(capacity + block, capacity + block)) {}

    // The first block: the given vectors (as many as fit), then random
    // columns, fixed seed per process (runs repeat bit for bit). A given
    // vector in the span of earlier ones is replaced like a vanished one.
    void start(const std::vector<PetscVector>* given) {
        const int k = given ? std::min(b_, int(given->size())) : 0;
        for (int j = 0; j < k; ++j) {
            const PetscScalar* x;
            COREMODAL_PETSC(VecGetArrayRead((*given)[j], &x));
            std::memcpy(V_.col(j), x, sizeof(double) * size_t(n_));
            COREMODAL_PETSC(VecRestoreArrayRead((*given)[j], &x));
        }
        std::mt19937_64 random(20261126u + unsigned(mpi_rank(comm_)));
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        for (int j = k; j < b_; ++j)
            for (PetscInt i = 0; i < n_; ++i) V_.col(j)[i] = uniform(random);
        normalise_new_block(0, b_, nullptr);
        m_ = b_;
        applied_ = 0;
    }

    bool full() const { return m_ + b_ > cap_; }

    // T applied to the oldest block not yet applied; the result, made
    // M-orthonormal to the basis, is the basis's next block.
    void expand() {
        solve_(b_, MV_.col(applied_), V_.col(m_));
        ++blocks_solved_;
        const Eigen::MatrixXd C1 = orthogonalise_against_basis(m_, b_);
        const Eigen::MatrixXd R1 = normalise_new_block(m_, b_, &C1);
        const Eigen::MatrixXd C2 = orthogonalise_against_basis(m_, b_, /*update_images=*/true);
        const Eigen::MatrixXd R2 = normalise_new_block(m_, b_, nullptr, /*images_known=*/true);
        // T V_applied = V_basis (C1 + C2 R1) + V_new (R2 R1).
        H_.block(0, applied_, m_, b_) += C1 + C2 * R1;
        H_.block(m_, applied_, b_, b_) = R2 * R1;
        applied_ += b_;
        m_ += b_;
    }

    // Ritz values of T (descending) and vectors (in the applied basis).
    struct Ritz {
        Eigen::VectorXd theta, residual;
        Eigen::MatrixXd S;
    };
    Ritz ritz() const {
        const Eigen::MatrixXd Haa = H_.topLeftCorner(applied_, applied_);
        const Eigen::MatrixXd sym = 0.5 * (Haa + Haa.transpose());
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sym);
        Ritz r;
        r.theta = eig.eigenvalues().reverse();
        r.S = eig.eigenvectors().rowwise().reverse();
        // ||T x - theta x||_M = ||H[a:m, 0:a] s|| (the unapplied block's coupling).
        const Eigen::MatrixXd E = H_.block(applied_, 0, m_ - applied_, applied_) * r.S;
        r.residual = E.colwise().norm().transpose();
        return r;
    }

    // Thick restart: the basis becomes the first `keep` Ritz vectors and
    // the block not yet applied.
    void restart(const Ritz& r, int keep) {
        const int a = applied_;  // keep <= a - b: the unapplied block lies past the Ritz vectors
        for (Columns* cols : {&V_, &MV_}) {
            right_multiply_in_place(*cols, 0, a, r.S.data(), a, keep);
            std::memmove(cols->col(keep), cols->col(a), sizeof(double) * size_t(n_) * size_t(b_));
        }
        const Eigen::MatrixXd E = H_.block(a, 0, b_, a) * r.S.leftCols(keep);
        H_.setZero();
        H_.topLeftCorner(keep, keep) = r.theta.head(keep).asDiagonal();
        H_.block(keep, 0, b_, keep) = E;
        applied_ = keep;
        m_ = keep + b_;
        ++restarts_;
    }

    // The first `count` Ritz vectors, as PETSc vectors.
    std::vector<PetscVector> ritz_vectors(const Ritz& r, int count) {
        std::vector<PetscVector> out(count);
        std::vector<double*> x(count);
        for (int j = 0; j < count; ++j) {
            COREMODAL_PETSC(MatCreateVecs(M_, out[j].out(), nullptr));
            COREMODAL_PETSC(VecGetArray(out[j], &x[j]));
        }
        for (PetscInt r0 = 0; r0 < n_; r0 += kPanelRows) {
            const PetscInt rows = std::min(kPanelRows, n_ - r0);
            gemm("N", "N", int(rows), count, applied_, 1.0, V_.col(0) + r0, n_, r.S.data(), applied_, 0.0, panel_.data(),
                 rows);
            for (int j = 0; j < count; ++j)
                std::memcpy(x[j] + r0, panel_.data() + size_t(j) * size_t(rows), sizeof(double) * size_t(rows));
        }
        for (int j = 0; j < count; ++j) COREMODAL_PETSC(VecRestoreArray(out[j], &x[j]));
        return out;
    }

    int blocks_solved() const { return blocks_solved_; }
    int restarts() const { return restarts_; }
    int applied() const { return applied_; }

private:
    // cols[first, first + out_width) = cols[first, first + width) * S (S:
    // width x out_width, leading dimension lds), in place, a panel of rows
    // at a time: each panel's rows are read whole before they are written.
    // A scratch copy of the product would cost a third of the basis's memory
    // (1 GB on a 540k-DOF model).
    void right_multiply_in_place(Columns& cols, int first, int width, const double* S, int lds, int out_width) {
        for (PetscInt r0 = 0; r0 < n_; r0 += kPanelRows) {
            const PetscInt rows = std::min(kPanelRows, n_ - r0);
            gemm("N", "N", int(rows), out_width, width, 1.0, cols.col(first) + r0, n_, S, lds, 0.0, panel_.data(), rows);
            for (int j = 0; j < out_width; ++j)
                std::memcpy(cols.col(first + j) + r0, panel_.data() + size_t(j) * size_t(rows),
                            sizeof(double) * size_t(rows));
        }
    }

    // Columns [first, first + count) less their M-projection on the basis
    // (columns 0 ... first); the coefficients are returned. With
    // update_images, their M-images (already in MV) are updated alike,
    // which saves a product with M in the second pass.
    Eigen::MatrixXd orthogonalise_against_basis(int first, int count, bool update_images = false) {
        Eigen::MatrixXd C = Eigen::MatrixXd::Zero(first, count);
        if (first == 0) return C;
        const OrthogonalizationScope logged;
        gemm("T", "N", first, count, int(n_), 1.0, MV_.col(0), n_, V_.col(first), n_, 0.0, C.data(), first);
        sum_over_processes(comm_, C.data(), int(C.size()));
        gemm("N", "N", int(n_), count, first, -1.0, V_.col(0), n_, C.data(), first, 1.0, V_.col(first), n_);
        if (update_images)
            gemm("N", "N", int(n_), count, first, -1.0, MV_.col(0), n_, C.data(), first, 1.0, MV_.col(first), n_);
        return C;
    }

    // Makes columns [first, first + count) M-orthonormal among themselves
    // (W = Y R with Y^T M Y = I: SVQB, through the eigenvalues of W^T M W)
    // and returns R. A direction that has vanished is replaced by a random
    // one orthogonal to everything (its row of R is zero). `projected`, when
    // given, holds the coefficients already removed, for the length of the
    // raw block.
    Eigen::MatrixXd normalise_new_block(int first, int count, const Eigen::MatrixXd* projected,
                                        bool images_known = false) {
        if (!images_known) times_M(count, V_.col(first), MV_.col(first));
        const OrthogonalizationScope logged;
        Eigen::MatrixXd G(count, count);
        gemm("T", "N", count, count, int(n_), 1.0, V_.col(first), n_, MV_.col(first), n_, 0.0, G.data(), count);
        sum_over_processes(comm_, G.data(), int(G.size()));
        G = 0.5 * (G + G.transpose()).eval();
        double length2 = G.diagonal().maxCoeff();
        if (projected) length2 = std::max(length2, (projected->colwise().squaredNorm().transpose() + G.diagonal()).maxCoeff());
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(G);
        const Eigen::VectorXd d = eig.eigenvalues();
        const Eigen::MatrixXd& Q = eig.eigenvectors();
        Eigen::MatrixXd scale = Eigen::MatrixXd::Zero(count, count);  // Y = W scale
        Eigen::MatrixXd R = Eigen::MatrixXd::Zero(count, count);
        std::vector<int> vanished;
        for (int i = 0; i < count; ++i) {
            if (d(i) <= kDeflation * kDeflation * length2 || d(i) <= 0) {
                vanished.push_back(i);
                continue;
            }
            scale.col(i) = Q.col(i) / std::sqrt(d(i));
            R.row(i) = std::sqrt(d(i)) * Q.col(i).transpose();
        }
        right_multiply_in_place(V_, first, count, scale.data(), count, count);
        right_multiply_in_place(MV_, first, count, scale.data(), count, count);
        for (int i : vanished) random_direction(first + i, first, count);
        return R;
    }

    // Column j: random, M-orthonormal to the basis and to the block's
    // columns other than j (those kept, and random ones made before it).
    void random_direction(int j, int first, int count) {
        std::mt19937_64 random(7919u * unsigned(j + 1) + unsigned(restarts_) + 104729u * unsigned(mpi_rank(comm_)));
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        for (PetscInt i = 0; i < n_; ++i) V_.col(j)[i] = uniform(random);
        std::vector<int> others;
        for (int c = 0; c < first + count; ++c)
            if (c != j) others.push_back(c);
        for (int pass = 0; pass < 2; ++pass) {
            times_M(1, V_.col(j), MV_.col(j));
            for (int c : others) {
                double dot = 0;
                for (PetscInt i = 0; i < n_; ++i) dot += MV_.col(c)[i] * V_.col(j)[i];
                sum_over_processes(comm_, &dot, 1);
                for (PetscInt i = 0; i < n_; ++i) V_.col(j)[i] -= dot * V_.col(c)[i];
            }
        }
        times_M(1, V_.col(j), MV_.col(j));
        double norm2 = 0;
        for (PetscInt i = 0; i < n_; ++i) norm2 += V_.col(j)[i] * MV_.col(j)[i];
        sum_over_processes(comm_, &norm2, 1);
        const double inv = 1.0 / std::sqrt(norm2);
        for (PetscInt i = 0; i < n_; ++i) {
            V_.col(j)[i] *= inv;
            MV_.col(j)[i] *= inv;
        }
    }

    // out = M in for `cols` columns: sparse_block_product.hpp in one
    // process, PETSc's product in parallel.
    void times_M(int cols, double* in, double* out) {
        if (SparseBlockProduct::handles(M_)) product_(M_, cols, in, out);
        else multiply(M_, n_, cols, in, out);
    }

    BlockSolve solve_;
    Mat M_;
    MPI_Comm comm_;
    PetscInt n_;
    int b_, cap_;
    Columns V_, MV_;
    std::vector<double> panel_;  // kPanelRows x the widest product
    Eigen::MatrixXd H_;  // H[:, c] = coefficients of T V[:, c] in the basis
    int m_ = 0, applied_ = 0, blocks_solved_ = 0, restarts_ = 0;
    SparseBlockProduct product_;
};

// The Ritz pairs in the order wanted: lambda = sigma + 1 / theta ascending
// among those below sigma (theta < 0: an indefinite factor), then those
// above it, nearest first (theta descending). With sigma below every
// eigenvalue all theta are positive and this is theta descending.
void order_as_wanted(BlockLanczos::Ritz& r) {
    const auto rank = [&](int i) { return std::pair<int, double>(r.theta(i) < 0 ? 0 : 1, -r.theta(i)); };
    std::vector<int> order(r.theta.size());
    for (int i = 0; i < int(order.size()); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rank(a) < rank(b); });
    BlockLanczos::Ritz sorted{r.theta, r.residual, r.S};
    for (int k = 0; k < int(order.size()); ++k) {
        sorted.theta(k) = r.theta(order[k]);
        sorted.residual(k) = r.residual(order[k]);
        sorted.S.col(k) = r.S.col(order[k]);
    }
    r = std::move(sorted);
}

// Converged Ritz pairs from the first wanted on, in order.
int converged_in_order(const BlockLanczos::Ritz& r, double tolerance) {
    int k = 0;
    while (k < r.theta.size() && r.theta(k) != 0 && r.residual(k) <= tolerance * std::abs(r.theta(k))) ++k;
    return k;
}

// Sixteen right-hand sides cost a quarter of sixteen single solves on the
// solid level (0.53 s against 2.2 s on case 03); 32 cost 0.64 s. The block
// follows the number wanted between those bounds.
int block_size_for(int wanted) { return std::clamp((wanted + 3) / 4 * 4, 8, 32); }

// Room for the wanted pairs, a block of extra Ritz vectors kept over a
// restart, and two blocks to grow.
int capacity_for(int wanted, int block) {
    const int needed = std::max(3 * wanted, wanted + 6 * block);
    return (needed + block - 1) / block * block;
}

// No bound on the passes but the restarts (a random start).
constexpr int kNoPassLimit = std::numeric_limits<int>::max();

// Expands and restarts until `wanted` pairs have converged or the restarts
// run out (true; the pairs converged in order, lambda = sigma + 1 / theta,
// in `out`), or until `pass_limit` passes have gone by without that
// (false: the caller drops the start).
bool iterate(BlockLanczos& lanczos, double sigma, const BlockLanczosRequest& request, int pass_limit,
             BlockLanczosResult& out) {
    const int block = out.block_size;
    for (;;) {
        lanczos.expand();
        BlockLanczos::Ritz r = lanczos.ritz();
        order_as_wanted(r);
        const int converged = converged_in_order(r, request.tolerance);
        if (converged >= request.wanted || lanczos.restarts() >= request.max_restarts) {
            for (int i = 0; i < converged; ++i) out.eigenvalues.push_back(sigma + 1.0 / r.theta(i));
            out.vectors = lanczos.ritz_vectors(r, converged);
            return true;
        }
        if (lanczos.blocks_solved() >= pass_limit) return false;
        if (lanczos.full()) {
            // Keep the wanted pairs and half the rest (Krylov-Schur's rule;
            // keeping only the wanted ones and half a block took 25 blocks
            // on case 03's coarse mesh against 14), leaving room for a block
            // to grow.
            const int room = lanczos.applied() - block;
            const int keep = std::min(room, std::max(request.wanted + block / 2, (room + request.wanted) / 2));
            lanczos.restart(r, keep);
        }
    }
}

}  // namespace

int predicted_start_passes(int block, int capacity) { return 2 * capacity / block; }

bool block_lanczos_fits(PetscInt n, int wanted) {
    const int block = block_size_for(wanted);
    return wanted > 0 && wanted <= kBlockLanczosMostWanted && capacity_for(wanted, block) + block <= n;
}

BlockLanczosResult block_lanczos_lowest(Mat F, Mat M, double sigma, const BlockLanczosRequest& request) {
    PetscInt n_local;
    COREMODAL_PETSC(MatGetLocalSize(M, &n_local, nullptr));
    return block_lanczos_lowest(factor_solve(F, M, n_local), M, sigma, request);
}

BlockLanczosResult block_lanczos_lowest(const BlockSolve& solve, Mat M, double sigma,
                                        const BlockLanczosRequest& request) {
    PetscInt n, n_local;
    COREMODAL_PETSC(MatGetSize(M, &n, nullptr));
    COREMODAL_PETSC(MatGetLocalSize(M, &n_local, nullptr));
    PetscInt opt_bs = block_size_for(request.wanted), opt_ncv = 0;
    COREMODAL_PETSC(PetscOptionsGetInt(nullptr, nullptr, "-block_lanczos_bs", &opt_bs, nullptr));
    const int block = int(opt_bs);
    COREMODAL_PETSC(PetscOptionsGetInt(nullptr, nullptr, "-block_lanczos_ncv", &opt_ncv, nullptr));
    const int capacity = opt_ncv ? int(opt_ncv) : capacity_for(request.wanted, std::max(block, 1));
    // The experts' values: a restart keeps the wanted pairs and needs room
    // for two blocks beside them.
    if (block < 1 || capacity < request.wanted + 4 * block || capacity + block > n)
        throw InputError("-block_lanczos_bs " + std::to_string(block) + " -block_lanczos_ncv " +
                         std::to_string(capacity) + " for " + std::to_string(request.wanted) + " pairs of a model with " +
                         std::to_string(n) + " unknowns: expected a block of at least 1 and a basis of at least " +
                         "the pairs + 4 blocks and at most the unknowns - 1 block");
    BlockLanczosResult out;
    out.block_size = block;
    out.started_from = request.start ? std::min(block, int(request.start->size())) : 0;
    auto lanczos = std::make_unique<BlockLanczos>(solve, M, n_local, block, capacity);
    lanczos->start(request.start);
    const int pass_limit = out.started_from > 0 ? predicted_start_passes(block, capacity) : kNoPassLimit;
    if (!iterate(*lanczos, sigma, request, pass_limit, out)) {
        // The given start is no better than a random one here: start afresh
        // (the same steps, bit for bit, as without it). Nothing is kept: the
        // thick restart has no locked pairs to carry over, and a fresh
        // random start reaches the tolerance the usual way.
        out.abandoned_start_passes = lanczos->blocks_solved();
        const int abandoned_restarts = lanczos->restarts();
        lanczos.reset();  // its basis's memory before the new one's
        lanczos = std::make_unique<BlockLanczos>(solve, M, n_local, block, capacity);
        lanczos->start(nullptr);
        iterate(*lanczos, sigma, request, kNoPassLimit, out);
        out.restarts = abandoned_restarts;
    }
    out.blocks_solved = out.abandoned_start_passes + lanczos->blocks_solved();
    out.restarts += lanczos->restarts();
    return out;
}

}  // namespace coremodal
