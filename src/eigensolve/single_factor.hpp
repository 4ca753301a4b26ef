// The shift-and-invert operator from a single-precision LDL^T of
// A = K - sigma M (issue 39): MUMPS's single-precision library (SMUMPS,
// called directly: Debian's PETSc 3.18 cannot select it) factors A
// converted to float, and every solve is refined in double precision
// (residual with the double A, correction through the single factor) until
// its backward error is that of a double-precision solve. The factor has
// half the bytes of the double one and its numeric step runs on sgemm, so
// the factorization and every pass over the factor cost about half
// (bench/results/log.md, "Single-precision factor").
//
// The factor's negative pivots (INFOG(12)) are the exact inertia of A + E,
// E the factor's backward error; they count the eigenvalues of (K, M)
// below sigma only when no eigenvalue lies within the bound
// count_margin() of sigma (docs/theory/methods.md, "A count from a
// single-precision factor"): single_count_proven says whether the verified
// modes show that. One process only (sequential SMUMPS); in parallel the
// double factor stays. Internal to eigensolve/.
#pragma once

#include "common/petsc_handle.hpp"
#include "eigensolve/sparse_block_product.hpp"

#include <petscmat.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace coremodal {

// Which precision factors K - sigma M on the one-factor path, and why (the
// run says it). -factor_precision single | double | auto. auto is double
// for now: on case 03 the single factor's refined passes and Rayleigh-Ritz
// cleanup (single_refinement.hpp: 32 passes over a factor of half the
// bytes against the double's 14) cost more than its cheaper factorization
// saved (bench/results/log.md, "Fewer passes"). single is one process only (sequential
// SMUMPS); in parallel the double factor stays.
struct FactorPrecision {
    bool single = false;
    std::string asked = "auto";  // what -factor_precision said (auto when not given)
    std::string why;
};
FactorPrecision factor_precision_choice(MPI_Comm comm);

// A refined solve that did not reach the double-precision backward error
// within kMaxRefinementSteps, or stopped improving (A too ill-conditioned
// for the single factor: cond(A) u_single near 1). The caller falls back
// to the double factor and says so.
class RefinementStalled : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Refinement stops when every column's normwise backward error
// ||b - A x|| / (||A||_1 ||x|| + ||b||) is below this: a few hundred times
// double precision's unit round-off, what a backward-stable double LDL^T
// solve gives on these matrices (up to ~80 entries a row). Block Lanczos's
// tolerance (1e-10 on ||T x - theta x|| / theta) then sees the operator
// as exact as with the double factor.
inline constexpr double kRefinedBackwardError = 1e-13;
// At most this many corrections per solve: each is a pass over the factor,
// so beyond three the single factor's passes cost more than the double's.
inline constexpr int kMaxRefinementSteps = 4;

class SingleLdlt {
public:
    // Factors A (one process, SeqAIJ, symmetric) in single precision: the
    // ordering MUMPS chooses (as the double factor through PETSc),
    // ICNTL(13) = 1 as there, out of core decided as there
    // (petsc_algebra.hpp). Throws SolveError when the factorization fails
    // (a zero pivot in single precision: sigma too close to an eigenvalue).
    explicit SingleLdlt(Mat A);
    ~SingleLdlt();
    SingleLdlt(const SingleLdlt&) = delete;
    SingleLdlt& operator=(const SingleLdlt&) = delete;

    // INFOG(12): the negative pivots, the inertia of A + E.
    long negative_pivots() const;
    bool out_of_core() const;
    // MUMPS's in-core estimate of the factor, MB (INFOG(17)).
    long estimate_mb() const;

    // out = A^-1 in for `cols` columns (column-major, leading dimension the
    // row count), refined in double until every column's backward error is
    // below `target` (RefinementStalled when it stalls).
    void solve(int cols, const double* in, double* out, double target = kRefinedBackwardError);

    // The largest normwise backward error of a first, unrefined solve
    // measured so far: the factor's backward error, ||E|| <= this x ||A||_1
    // as the count's bound takes it (factor_backward_error's margin in
    // single_count_proven).
    double factor_backward_error() const { return first_error_; }
    double norm_1() const { return norm_1_; }
    // The most corrections one solve took, for the run's report.
    int most_steps() const { return most_steps_; }
    int solves() const { return solves_; }
    // Every pass over the factor (a block of right-hand sides each): the
    // cost the refinement is judged by.
    int factor_passes() const { return factor_passes_; }

private:
    struct Mumps;
    std::unique_ptr<Mumps> mumps_;
    Mat A_;
    PetscInt n_ = 0;
    double norm_1_ = 0;
    double first_error_ = 0;
    int most_steps_ = 0, solves_ = 0, factor_passes_ = 0;
    std::vector<float> rhs_;
    std::vector<double> residual_, product_out_;
    SparseBlockProduct product_;
};

// The margin the count needs: the inertia of A + E equals that of A when
// every eigenvalue mu of the symmetric A has |mu| > ||E||_2 (Weyl), and
// ||E||_2 <= kBackwardErrorMargin x the measured backward error x ||A||_1.
inline constexpr double kBackwardErrorMargin = 10.0;
double count_margin(const SingleLdlt& F);

// Whether the single factor's count is proven by the verified pairs
// (lambdas ascending, vectors): every pair's eigenvalue mu = (lambda -
// sigma) rho, rho = x^T M x / x^T x, of A stays outside the margin. The
// pair nearest sigma above and below is among them (block Lanczos finds
// the largest |theta| = 1 / |lambda - sigma| first).
bool single_count_proven(const SingleLdlt& F, Mat M, double sigma, const std::vector<double>& lambdas,
                         const std::vector<PetscVector>& vectors);

}  // namespace coremodal
