#include "eigensolve/modal_solver.hpp"

#include "eigensolve/band_edge.hpp"
#include "eigensolve/block_lanczos.hpp"
#include "eigensolve/predicted_edge.hpp"
#include "eigensolve/shift_invert_steps.hpp"

#include "common/error.hpp"
#include "common/heartbeat.hpp"
#include "eigensolve/petsc_algebra.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <sstream>

namespace coremodal {
using namespace shift_invert;
namespace {

PetscHandle<EPS, EPSDestroy> configure(Mat K, Mat M, double sigma, int nev, const SolveRequest& request) {
    PetscHandle<EPS, EPSDestroy> eps = krylov_schur_at(K, M, sigma);
    COREMODAL_PETSC(EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE));
    COREMODAL_PETSC(EPSSetDimensions(eps, nev, PETSC_DEFAULT, PETSC_DEFAULT));
    COREMODAL_PETSC(EPSSetTolerances(eps, request.tolerance, request.max_iterations));
    ST st;
    COREMODAL_PETSC(EPSGetST(eps, &st));
    const PC pc = direct_shift_and_invert(st);
    COREMODAL_PETSC(PCSetType(pc, PCCHOLESKY));
    // K - sigma M is positive definite (sigma < 0), so a plain Cholesky
    // factor serves. In one process CHOLMOD's METIS ordering gives a smaller
    // factor than Debian's MUMPS (PORD): 30 % less time on a 181k-DOF rest
    // roll (bench/results/log.md). In parallel, MUMPS.
    COREMODAL_PETSC(PCFactorSetMatSolverType(pc, shift_invert_factor_package(PetscObjectComm((PetscObject)K))));
    // Experts override any of the above from the command line (-eps_*, -st_*).
    COREMODAL_PETSC(EPSSetFromOptions(eps));
    return eps;
}

// The vectors as the columns of one dense matrix with M's rows, so that K
// and M pass over their entries once for all the modes: one product each
// where one vector at a time took 4 passes per mode (56 on case 03's solid
// level, 2.8 s; bench/results/log.md).
PetscMatrix as_columns(Mat M, const std::vector<PetscVector>& X) {
    PetscInt local_rows = 0;
    COREMODAL_PETSC(MatGetLocalSize(M, &local_rows, nullptr));
    PetscMatrix C;
    COREMODAL_PETSC(MatCreateDense(PetscObjectComm((PetscObject)M), local_rows, PETSC_DECIDE, PETSC_DETERMINE,
                                   PetscInt(X.size()), nullptr, C.out()));
    PetscScalar* c = nullptr;
    COREMODAL_PETSC(MatDenseGetArrayWrite(C, &c));
    for (size_t j = 0; j < X.size(); ++j) {
        const PetscScalar* x = nullptr;
        COREMODAL_PETSC(VecGetArrayRead(X[j], &x));
        std::copy(x, x + local_rows, c + j * size_t(local_rows));
        COREMODAL_PETSC(VecRestoreArrayRead(X[j], &x));
    }
    COREMODAL_PETSC(MatDenseRestoreArrayWrite(C, &c));
    return C;
}

PetscMatrix product(Mat A, Mat X) {
    PetscMatrix AX;
    COREMODAL_PETSC(MatMatMult(A, X, MAT_INITIAL_MATRIX, PETSC_DEFAULT, AX.out()));
    return AX;
}

// The checks of modes X (lambdas): each one's relative residual
// ||K x - lambda M x|| / (||K||_1 ||x||) (||K||_1 bounds the spectral norm
// of the symmetric K from above and is cheap), and the Gram matrix X^T M X,
// summed over the processes.
struct ModeChecks {
    std::vector<double> residuals;
    std::vector<double> gram;  // k x k, column-major
};

ModeChecks check_modes(Mat K, Mat M, const std::vector<PetscVector>& X, const std::vector<double>& lambdas) {
    const size_t k = X.size();
    PetscReal K_norm;
    COREMODAL_PETSC(MatNorm(K, NORM_1, &K_norm));
    const PetscMatrix columns = as_columns(M, X), KX = product(K, columns), MX = product(M, columns);
    PetscInt n = 0;
    COREMODAL_PETSC(MatGetLocalSize(M, &n, nullptr));
    const PetscScalar *x = nullptr, *kx = nullptr, *mx = nullptr;
    COREMODAL_PETSC(MatDenseGetArrayRead(columns, &x));
    COREMODAL_PETSC(MatDenseGetArrayRead(KX, &kx));
    COREMODAL_PETSC(MatDenseGetArrayRead(MX, &mx));
    // Per column: ||K x - lambda M x||^2, ||x||^2; then the Gram matrix.
    std::vector<double> sums(2 * k + k * k, 0.0);
    for (size_t j = 0; j < k; ++j) {
        const size_t c = j * size_t(n);
        for (PetscInt i = 0; i < n; ++i) {
            const double r = kx[c + i] - lambdas[j] * mx[c + i];
            sums[j] += r * r;
            sums[k + j] += x[c + i] * x[c + i];
        }
        for (size_t l = 0; l < k; ++l)
            for (PetscInt i = 0; i < n; ++i) sums[2 * k + j * k + l] += x[l * size_t(n) + i] * mx[c + i];
    }
    COREMODAL_PETSC(MatDenseRestoreArrayRead(columns, &x));
    COREMODAL_PETSC(MatDenseRestoreArrayRead(KX, &kx));
    COREMODAL_PETSC(MatDenseRestoreArrayRead(MX, &mx));
    MPI_Allreduce(MPI_IN_PLACE, sums.data(), int(sums.size()), MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)M));
    ModeChecks out;
    for (size_t j = 0; j < k; ++j) out.residuals.push_back(std::sqrt(sums[j]) / (K_norm * std::sqrt(sums[k + j])));
    out.gram.assign(sums.begin() + 2 * long(k), sums.end());
    return out;
}

// K - sigma M is positive definite for sigma < 0 in exact arithmetic; a zero
// pivot means round-off swamps its smallest eigenvalues (a model whose
// eigenvalues span more than double precision holds) or a part without
// stiffness and mass.
std::string zero_pivot_text(double sigma) {
    std::ostringstream s;
    s << "the Cholesky factor of K - sigma M met a zero pivot at sigma = " << sigma
      << " rad^2/s^2, where it is positive definite in exact arithmetic: the model's eigenvalues span more "
         "than double precision resolves (cells far longer than thick, as in a body a thousandth as long as it "
         "is wide), or a part has neither stiffness nor mass; expected a body at least about a hundredth as long "
         "as its diameter";
    return s.str();
}

Attempt run_eps(Mat K, Mat M, double sigma, int nev, const SolveRequest& request) {
    auto eps = configure(K, M, sigma, nev, request);
    const PetscErrorCode solved = EPSSolve(eps);
    if (solved == PETSC_ERR_MAT_CH_ZRPVT || solved == PETSC_ERR_MAT_LU_ZRPVT) throw SolveError(zero_pivot_text(sigma));
    COREMODAL_PETSC(solved);
    return converged_pairs(eps, K);
}

// The Cholesky factor of K - sigma M (sigma < 0: definite) by the package
// shift_invert_factor_package names.
PetscMatrix definite_factor(Mat K, Mat M, double sigma) {
    PetscMatrix F;
    const PetscErrorCode factored =
        factor_symmetric(shifted(K, M, sigma), shift_invert_factor_package(PetscObjectComm((PetscObject)K)), F);
    if (factored == PETSC_ERR_MAT_CH_ZRPVT || factored == PETSC_ERR_MAT_LU_ZRPVT) throw SolveError(zero_pivot_text(sigma));
    COREMODAL_PETSC(factored);
    MatFactorError factor_error;
    COREMODAL_PETSC(MatFactorGetError(F, &factor_error));
    if (factor_error != MAT_FACTOR_NOERROR) throw SolveError(zero_pivot_text(sigma));
    return F;
}

// The lowest nev pairs at the negative shift: block Lanczos where it
// applies (`blocks`: on a small model too), else SLEPc's Krylov-Schur.
Attempt solve_below(Mat K, Mat M, double sigma, int nev, const SolveRequest& request, const Progress& progress,
                    bool blocks) {
    PetscInt n_dofs;
    COREMODAL_PETSC(MatGetSize(K, &n_dofs, nullptr));
    if (!block_lanczos_applies(n_dofs, nev, blocks)) return run_eps(K, M, sigma, nev, request);
    const PetscMatrix F = definite_factor(K, M, sigma);
    say_if_out_of_core(F, progress);
    return block_lanczos_attempt(F, M, sigma, nev, request, progress);
}

// Retries after a failed completeness check before giving up.
constexpr int kMaxRetries = 2;

// The shift for a retry: half the lowest elastic eigenvalue found below zero
// (negative, so rigid modes stay harmless), or the old shift if that is closer.
double better_shift(const std::vector<double>& lambdas, double scale, double old_sigma) {
    for (double lambda : lambdas)
        if (lambda > kRigidEigenvalueFraction * scale) return std::max(old_sigma, -kShiftFraction * lambda);
    return old_sigma;
}

std::string format_count_mismatch(long pivots, long found, double sigma) {
    std::ostringstream s;
    s << "the shifted factor K - sigma M at sigma = " << sigma << " rad^2/s^2 (" << eigenvalue_hz(sigma) << " Hz) has "
      << pivots << " negative pivots, but " << found << " modes were found below it: " << pivots - found
      << " mode(s) were missed; raise [analysis] max_iterations or the number of modes";
    return s.str();
}

std::string band_text(const SolveRequest& r) {
    std::ostringstream s;
    s << "[analysis] band = [" << eigenvalue_hz(r.lambda_min.value_or(0.0)) << " Hz, " << eigenvalue_hz(*r.lambda_max)
      << " Hz]";
    return s.str();
}

long count_below(Mat K, Mat M, double sigma);

// Eigenvalues below a band's lower edge (0 when it lies among the rigid
// modes: they belong to the band) and below its upper edge, by inertia.
struct BandCount {
    long below_lower = 0, below_upper = 0;
    bool empty() const { return below_upper == below_lower; }
};

// Two factorisations, no solve. Refuses, before any solve, a band the model
// cannot answer: one reaching above its every eigenvalue (frequencies beyond
// what the mesh resolves), or one that needs more modes than the limit.
BandCount count_band(Mat K, Mat M, const SolveRequest& r, long n_dofs, const Progress& progress) {
    progress("counting the modes below the band's edges (inertia of K - sigma M)");
    const Heartbeat beat("counting the modes below the band's edges", progress);
    BandCount c;
    c.below_upper = count_below(K, M, *r.lambda_max);
    if (r.lambda_min.value_or(0.0) > rigid_line(r)) c.below_lower = count_below(K, M, *r.lambda_min);
    if (c.below_upper >= n_dofs)
        throw InputError(band_text(r) + " reaches above every eigenvalue of the model: all " + std::to_string(n_dofs) +
                         " lie below its upper edge (inertia count), and frequencies that high are beyond what the "
                         "mesh resolves; expected a band within the model's spectrum: lower the upper edge");
    if (!c.empty() && c.below_upper > kMaxModesPerProblem)
        throw InputError(band_text(r) + ": " + std::to_string(c.below_upper - c.below_lower) +
                         " modes lie in the band and " + std::to_string(c.below_upper) +
                         " below its upper edge (inertia counts); the solver computes every mode below the upper "
                         "edge, at most " + std::to_string(kMaxModesPerProblem) +
                         ": lower the upper edge or ask for the lowest modes ([analysis] modes)");
    return c;
}

// An empty band, proven by the counts alone: as many eigenvalues below the
// upper edge as below the lower one, none of them computed.
Verification empty_band_verification(const BandCount& c, double lambda_max) {
    Verification v;
    v.check_shift = lambda_max;
    v.negative_pivots_at_shift = c.below_upper;
    v.modes_below_shift = c.below_lower;
    v.eigenvalues_below_band = c.below_lower;
    v.complete = true;
    return v;
}

}  // namespace

namespace shift_invert {

// Krylov-Schur on the symmetric-definite pencil (K, M), aimed at sigma.
PetscHandle<EPS, EPSDestroy> krylov_schur_at(Mat K, Mat M, double sigma) {
    PetscHandle<EPS, EPSDestroy> eps;
    COREMODAL_PETSC(EPSCreate(PetscObjectComm((PetscObject)K), eps.out()));
    COREMODAL_PETSC(EPSSetOperators(eps, K, M));
    COREMODAL_PETSC(EPSSetProblemType(eps, EPS_GHEP));
    COREMODAL_PETSC(EPSSetType(eps, EPSKRYLOVSCHUR));
    COREMODAL_PETSC(EPSSetTarget(eps, sigma));
    return eps;
}

// Every converged pair of a solved EPS, in ascending order of eigenvalue.
Attempt converged_pairs(EPS eps, Mat K) {
    PetscInt nconv;
    COREMODAL_PETSC(EPSGetConverged(eps, &nconv));
    Attempt a;
    a.n_converged = static_cast<int>(nconv);
    std::vector<std::pair<double, int>> order;
    for (PetscInt i = 0; i < nconv; ++i) {
        PetscScalar kr;
        COREMODAL_PETSC(EPSGetEigenvalue(eps, i, &kr, nullptr));
        order.emplace_back(PetscRealPart(kr), int(i));
    }
    std::sort(order.begin(), order.end());
    for (auto [lambda, i] : order) {
        PetscVector x;
        COREMODAL_PETSC(MatCreateVecs(K, x.out(), nullptr));
        COREMODAL_PETSC(EPSGetEigenvector(eps, i, x, nullptr));
        a.lambdas.push_back(lambda);
        a.vectors.push_back(std::move(x));
    }
    return a;
}

// |lambda| below this is a rigid-body mode (tolerances.hpp).
double rigid_line(const SolveRequest& r) { return kRigidEigenvalueFraction * r.lambda_scale; }

// Below this many unknowns SLEPc's one-vector Krylov-Schur stays: the
// harmonic level's sections and coarse solid meshes keep the path they were
// verified on, where a solve is cheap anyway. A choice, not a measured
// crossover: case 03's coarse mesh (24,960 unknowns) already takes the
// block method.
constexpr PetscInt kBlockLanczosMinDofs = 20000;

// The block method on the factor's multi-right-hand-side solves
// (block_lanczos.hpp: why), in one process or several (MUMPS's distributed
// factor), on a model large enough for the pairs wanted
// (block_lanczos_fits), unless the user turned it off (-block_lanczos false)
// or chose SLEPc's method or its factor on the command line (-eps_type,
// -st_pc_factor_mat_solver_type).
bool block_lanczos_applies(PetscInt n_dofs, int wanted, bool small_too) {
    if ((n_dofs < kBlockLanczosMinDofs && !small_too) || !block_lanczos_fits(n_dofs, wanted)) return false;
    PetscBool on = PETSC_TRUE, eps_type = PETSC_FALSE, st_factor = PETSC_FALSE;
    COREMODAL_PETSC(PetscOptionsGetBool(nullptr, nullptr, "-block_lanczos", &on, nullptr));
    COREMODAL_PETSC(PetscOptionsHasName(nullptr, nullptr, "-eps_type", &eps_type));
    COREMODAL_PETSC(PetscOptionsHasName(nullptr, nullptr, "-st_pc_factor_mat_solver_type", &st_factor));
    return on && !eps_type && !st_factor;
}

// The caller's wanted pairs, residual and restarts, and its predicted
// vectors as the first block.
static BlockLanczosRequest lanczos_request(int wanted, const SolveRequest& request) {
    BlockLanczosRequest out{wanted, request.tolerance, request.max_iterations};
    out.start = request.predicted_vectors.get();
    return out;
}

// The pairs block Lanczos found, its passes said through `progress`.
static Attempt as_attempt(BlockLanczosResult r, const Progress& progress) {
    Attempt a;
    if (r.abandoned_start_passes)
        a.start_dropped = "block Lanczos's start from " + std::to_string(r.started_from) +
                          " predicted mode(s) dropped for a random one after " +
                          std::to_string(r.abandoned_start_passes) + " passes without converging";
    progress("block Lanczos: " + std::to_string(r.blocks_solved) + " passes over the factor with " +
             std::to_string(r.block_size) + " vectors each, " + std::to_string(r.restarts) + " restart(s)" +
             (r.started_from ? ", started from " + std::to_string(r.started_from) + " predicted mode(s)" : "") +
             (r.abandoned_start_passes ? " that had not converged in " + std::to_string(r.abandoned_start_passes) +
                                             " passes (what a random start takes), then from a random start"
                                       : ""));
    a.n_converged = static_cast<int>(r.eigenvalues.size());
    a.lambdas = std::move(r.eigenvalues);
    a.vectors = std::move(r.vectors);
    return a;
}

Attempt block_lanczos_attempt(Mat F, Mat M, double sigma, int wanted, const SolveRequest& request,
                              const Progress& progress) {
    return as_attempt(block_lanczos_lowest(F, M, sigma, lanczos_request(wanted, request)), progress);
}

Attempt block_lanczos_attempt(const BlockSolve& solve, Mat M, double sigma, int wanted, const SolveRequest& request,
                              const Progress& progress) {
    return as_attempt(block_lanczos_lowest(solve, M, sigma, lanczos_request(wanted, request)), progress);
}

void say_if_out_of_core(Mat F, const Progress& progress) {
    if (!factor_out_of_core(F)) return;
    PetscInt estimate_mb = 0;
    COREMODAL_PETSC(MatMumpsGetInfog(F, 17, &estimate_mb));
    progress("the factor is kept on disk (MUMPS out of core: its analysis estimated " + std::to_string(estimate_mb) +
             " MB, more than " + std::to_string(int(100 * kInCoreShare)) +
             " % of the memory the run may take (the machine's free memory, its control group's limit or "
             "-max_memory_mb), or -mat_mumps_icntl_22 1 was given); each pass over it reads the disk");
}

// The first n_report modes of a proven-complete attempt, M-normalised, with
// their residuals and the verification.
SolvedModes verified_modes(Mat K, Mat M, Attempt& a, int n_report, double check, long pivots, long found_below) {
    SolvedModes out;
    for (int i = 0; i < n_report; ++i) {
        out.eigenvalues.push_back(a.lambdas[i]);
        out.vectors.push_back(std::move(a.vectors[i]));
    }
    const ModeChecks checks = check_modes(K, M, out.vectors, out.eigenvalues);
    // M-normalised: x / sqrt(x^T M x); the residual does not change with the
    // scale, the Gram matrix scales by both columns' factors.
    const size_t k = out.vectors.size();
    std::vector<double> scale(k);
    for (size_t j = 0; j < k; ++j) {
        scale[j] = 1.0 / std::sqrt(checks.gram[j * k + j]);
        COREMODAL_PETSC(VecScale(out.vectors[j], scale[j]));
    }
    out.relative_residuals = checks.residuals;
    auto& v = out.verification;
    v.max_relative_residual = *std::max_element(out.relative_residuals.begin(), out.relative_residuals.end());
    v.max_orthonormality_error = 0;
    for (size_t j = 0; j < k; ++j)
        for (size_t l = 0; l <= j; ++l) {
            const double normalised = scale[j] * scale[l] * checks.gram[j * k + l];
            v.max_orthonormality_error =
                std::max(v.max_orthonormality_error, std::abs(normalised - (l == j ? 1.0 : 0.0)));
        }
    v.check_shift = check;
    v.negative_pivots_at_shift = pivots;
    v.modes_below_shift = found_below;
    v.complete = true;
    return out;
}

std::string unconverged_text(int n_converged, int wanted, const SolveRequest& request) {
    std::ostringstream s;
    s << "converged " << n_converged << " of " << wanted << " requested modes (tolerance " << request.tolerance
      << "); raise [analysis] max_iterations (now " << request.max_iterations << ") or loosen [analysis] tolerance";
    return s.str();
}

}  // namespace shift_invert

bool in_band(double lambda, const SolveRequest& request) {
    if (!request.lambda_max) return true;
    const double value = std::abs(lambda) < rigid_line(request) ? 0.0 : lambda;
    return value >= request.lambda_min.value_or(0.0) && value <= *request.lambda_max;
}

const char* shift_invert_factor_package(MPI_Comm comm) { return mpi_size(comm) == 1 ? MATSOLVERCHOLMOD : MATSOLVERMUMPS; }

namespace {

long count_below(Mat K, Mat M, double sigma) {
    const std::string what = "K - sigma M at sigma = " + std::to_string(sigma) + " rad^2/s^2";
    return negative_eigenvalue_count(shifted(K, M, sigma), what.c_str());
}

void require_symmetric_problem(const OperatorSet& ops) {
    if (ops.quadratic())
        throw SolveError("the operator set has a gyroscopic or damping term: a quadratic eigenproblem, which the "
                         "symmetric solver cannot take");
}

// How many modes the request needs (every one below a band's upper edge, by
// inertia), or an empty band's proof without a solve.
struct Wanted {
    int n_modes = 0;
    std::optional<Verification> empty_band;
    std::optional<BandCount> band;  // a band's counts, which also prove the solve complete
};

Wanted wanted_modes(Mat K, Mat M, const SolveRequest& request, long n_dofs, const Progress& progress) {
    Wanted w{request.n_modes, std::nullopt, std::nullopt};
    if (request.lambda_max) {
        const BandCount band = count_band(K, M, request, n_dofs, progress);
        if (band.empty()) {
            w.empty_band = empty_band_verification(band, *request.lambda_max);
            return w;
        }
        w.n_modes = static_cast<int>(band.below_upper);
        w.band = band;
    }
    if (w.n_modes > n_dofs)
        throw InputError("[analysis] modes = " + std::to_string(w.n_modes) + " asks for more modes than the model "
                         "has degrees of freedom (" + std::to_string(n_dofs) + "); ask for at most " +
                         std::to_string(n_dofs) + " or refine the mesh");
    COREMODAL_ASSERT(w.n_modes > 0);
    return w;
}

SolvedModes solve_generalized(Mat K, Mat M, const SolveRequest& request, const Progress& progress) {
    PetscInt n_dofs;
    COREMODAL_PETSC(MatGetSize(K, &n_dofs, nullptr));
    const double scale = request.lambda_scale;
    const Wanted w = wanted_modes(K, M, request, n_dofs, progress);
    if (w.empty_band) return SolvedModes{{}, {}, {}, *w.empty_band};
    const int wanted = w.n_modes;
    if (const std::optional<double> edge = predicted_shift(request, wanted))
        if (std::optional<SolvedModes> solved = solve_at_predicted_edge(K, M, request, wanted, *edge, n_dofs, progress))
            return std::move(*solved);

    double sigma = -kShiftFraction * scale;
    int nev = std::min<int>(n_dofs, wanted + std::max(kMinExtraModes, wanted / 4));
    for (int attempt = 0;; ++attempt) {
        // A retry takes blocks on any model: one-vector Krylov may miss a copy of a double eigenvalue,
        // a block carries every copy up to its size (docs/validation/reliability.md, "A double
        // eigenvalue found whole").
        const bool blocks = attempt > 0;
        progress("factorising K - sigma M (" + std::string(shift_invert_factor_package(PetscObjectComm((PetscObject)K))) +
                 " Cholesky, sigma = " + std::to_string(sigma) + ") and solving for " + std::to_string(nev) +
                 " modes (" + (block_lanczos_applies(n_dofs, nev, blocks) ? "block Lanczos" : "SLEPc Krylov-Schur") +
                 "); MUMPS LDL^T at the band edge for the count");
        Attempt a = [&] {
            const Heartbeat beat("factorising K - sigma M and solving", progress);
            return solve_below(K, M, sigma, nev, request, progress, blocks);
        }();
        const int n_report = reported_count(a.lambdas, wanted, scale);
        if (n_report < wanted) throw SolveError(unconverged_text(a.n_converged, wanted, request));
        // A band's upper edge was counted before the solve: as many modes
        // found below it as it has eigenvalues there proves them all found.
        if (w.band && n_report == wanted) {
            const double edge = *request.lambda_max;
            const long below_edge = std::count_if(a.lambdas.begin(), a.lambdas.end(), [&](double l) { return l < edge; });
            if (below_edge == w.band->below_upper)
                return verified_modes(K, M, a, n_report, edge, w.band->below_upper, below_edge);
        }
        const double check = check_point(a.lambdas, n_report, scale);
        progress("checking completeness: inertia of K - sigma M at the band edge");
        const long pivots = [&] {
            const Heartbeat beat("checking completeness", progress);
            return count_below(K, M, check);
        }();
        if (pivots == n_report) return verified_modes(K, M, a, n_report, check, pivots, n_report);
        if (attempt >= kMaxRetries || pivots < n_report || pivots >= n_dofs)
            throw SolveError(format_count_mismatch(pivots, n_report, check));
        // A shift far below the wanted modes squeezes them together in the
        // transformed spectrum and Krylov-Schur may skip some: move the shift
        // next to the lowest elastic mode found, and make room.
        sigma = better_shift(a.lambdas, scale, sigma);
        progress("inertia count says " + std::to_string(pivots) + " modes lie below the edge, " +
                 std::to_string(n_report) + " found: solving again with a larger subspace");
        nev = std::min<int>(n_dofs, int(pivots) + std::max(kMinExtraModes, int(pivots) / 4));
    }
}

}  // namespace

long count_eigenvalues_below(const OperatorSet& ops, double sigma) {
    require_symmetric_problem(ops);
    return count_below(EffectiveStiffness(ops).get(), ops.M(), sigma);
}

SolvedModes solve_modes(const OperatorSet& ops, const SolveRequest& request, const Progress& progress) {
    require_symmetric_problem(ops);
    return solve_generalized(EffectiveStiffness(ops).get(), ops.M(), request, progress);
}

}  // namespace coremodal
