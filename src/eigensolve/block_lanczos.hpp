// Eigenpairs of K x = lambda M x by block Lanczos on the shift-and-invert
// operator T = (K - sigma M)^-1 M, the lowest first.
//
// Why a block method (issue 19, bench/results/log.md): on the solid level a
// triangular solve with the factor of K - sigma M reads the whole factor
// (1.5 GB on case 03) twice and does two flops per entry, so it is bound by
// memory: 0.13 s each, 115 of them per solve with SLEPc's one-vector
// Krylov-Schur. A block of 16 right-hand sides reads the factor once per
// pass for all of them (MatMatSolve: BLAS-3 in the supernodes): 16 solves
// in 0.53 s instead of 2.2 s. The block also holds every member of a
// multiple eigenvalue at once (a bending pair, a free body's six rigid
// modes), which a one-vector Krylov space meets only through round-off.
//
// The method: T is self-adjoint in the M inner product. Blocks of b
// vectors are M-orthonormalised against all earlier ones (Gram-Schmidt
// twice, in blocks), so the Rayleigh quotient H = V^T M T V is available
// from the coefficients; its eigenvalues theta are Ritz values of T and
// lambda = sigma + 1 / theta. A Ritz pair has converged when its residual
// ||T x - theta x||_M (read off the last block's coupling, no extra solve)
// is below tolerance x theta: the criterion SLEPc applies to the same
// operator. When the basis is full it restarts thick: the best Ritz vectors
// and the last block are kept (Krylov-Schur's restart, in blocks).
//
// In parallel each process holds its rows of the basis (the rows of M it
// owns) and the factor is MUMPS's distributed one; the inner products are
// local dgemms summed over the processes, so every process holds the same
// small matrices and takes the same steps (case 03 on two processes: 0.75x
// the time of one, bench/results/log.md "Two processes").
//
// Two uses (eigensolve/modal_solver.cpp). Sigma below every eigenvalue
// (K - sigma M definite, a Cholesky factor): all theta are positive and
// the lowest lambda are the largest theta. Sigma inside the spectrum (an
// LDL^T factor, whose negative pivots count the eigenvalues below sigma):
// those eigenvalues are the negative theta, wanted first, the lowest
// lambda first; the pairs above sigma follow, nearest first.
#pragma once

#include "common/petsc_handle.hpp"

#include <petscmat.h>

#include <functional>
#include <vector>

namespace coremodal {

struct BlockLanczosRequest {
    int wanted = 0;            // the pairs sought, in the order above
    double tolerance = 1e-10;  // on ||T x - theta x||_M / theta
    int max_restarts = 500;
    // Optional: vectors near the wanted ones (M's layout), e.g. a coarser
    // model's modes at this mesh's nodes. The first block takes as many as
    // fit, random columns the rest. The start changes only how fast the
    // space holds the wanted pairs, never what is accepted (the same
    // residual test; the count is the factor's). Guarded: a start that has
    // not converged in the passes a random one takes is dropped for a
    // random start (predicted_start_passes).
    const std::vector<PetscVector>* start = nullptr;
};

struct BlockLanczosResult {
    // Converged pairs in the order above — lambda ascending, since every
    // eigenvalue below sigma lies below every one above it — as many as
    // converged in order (at least `wanted` unless the restarts ran out);
    // M-orthonormal vectors.
    std::vector<double> eigenvalues;
    std::vector<PetscVector> vectors;
    int block_size = 0;
    int blocks_solved = 0;  // passes over the factor
    int restarts = 0;
    int started_from = 0;  // given start vectors in the first block
    // Passes spent on the given start before it was dropped for a random
    // one (0: kept, or none given); blocks_solved counts them too.
    int abandoned_start_passes = 0;
};

// The passes a start from given vectors may take before it is dropped for
// a random start: two fillings of the basis (2 x capacity / block; 14 at
// the default sizes), which is what a random start takes — 13 passes on
// case 03's coarse mesh, 14 on its shipped one, 15 on the membrane of
// tests/unit/eigensolve/test_block_lanczos.cpp — where a good start takes
// 6-7 (bench/results/log.md, session 22). A bad start thus costs at most
// about twice a random one, instead of the membrane's 62 passes.
int predicted_start_passes(int block, int capacity);

// F: a factor of K - sigma M (any package with MatMatSolve). M: the mass,
// n x n, n at least the basis (a few times `wanted`: the caller keeps small
// models on SLEPc). The block size and basis follow `wanted`; experts set
// them with -block_lanczos_bs and -block_lanczos_ncv.
BlockLanczosResult block_lanczos_lowest(Mat F, Mat M, double sigma, const BlockLanczosRequest& request);

// The operator as a function: out = (K - sigma M)^-1 in for `cols` columns
// of this process's rows (column-major, leading dimension the local rows),
// e.g. the single-precision factor's refined solve (single_factor.hpp).
using BlockSolve = std::function<void(int cols, const double* in, double* out)>;
BlockLanczosResult block_lanczos_lowest(const BlockSolve& solve, Mat M, double sigma,
                                        const BlockLanczosRequest& request);

// Whether the method takes `wanted` pairs of an n-unknown model: its basis
// (about 3 x wanted vectors, twice over with their M-images) must fit the
// model, and stay a small multiple of SLEPc's for the memory; beyond
// kBlockLanczosMostWanted pairs SLEPc's Krylov-Schur, whose basis is bounded.
constexpr int kBlockLanczosMostWanted = 64;
bool block_lanczos_fits(PetscInt n, int wanted);

}  // namespace coremodal
