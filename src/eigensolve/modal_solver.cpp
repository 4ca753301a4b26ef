#include "eigensolve/modal_solver.hpp"

#include "eigensolve/band_edge.hpp"
#include "eigensolve/block_lanczos.hpp"

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
namespace {

// The shift sits this far below zero, in units of the first elastic
// eigenvalue: rigid-body modes (lambda = 0) then make K - sigma M definite
// instead of singular, and the wanted low modes stay well separated in the
// shift-and-invert spectrum 1 / (lambda - sigma).
constexpr double kShiftFraction = 0.5;
// Extra modes computed beyond those reported: they locate the gap where the
// inertia check is placed and catch a degenerate partner of the last mode.
constexpr int kMinExtraModes = 4;

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
    // roll (docs/performance.md). In parallel, MUMPS.
    COREMODAL_PETSC(PCFactorSetMatSolverType(pc, shift_invert_factor_package(PetscObjectComm((PetscObject)K))));
    // Experts override any of the above from the command line (-eps_*, -st_*).
    COREMODAL_PETSC(EPSSetFromOptions(eps));
    return eps;
}

// Relative residual ||K x - lambda M x|| / (||K||_1 ||x||); ||K||_1 bounds the
// spectral norm of the symmetric K from above and is cheap to compute.
double relative_residual(Mat K, Mat M, double K_norm, Vec x, double lambda) {
    PetscVector Kx, Mx;
    COREMODAL_PETSC(VecDuplicate(x, Kx.out()));
    COREMODAL_PETSC(VecDuplicate(x, Mx.out()));
    COREMODAL_PETSC(MatMult(K, x, Kx));
    COREMODAL_PETSC(MatMult(M, x, Mx));
    COREMODAL_PETSC(VecAXPY(Kx, -lambda, Mx));
    return vector_norm(Kx) / (K_norm * vector_norm(x));
}

void m_normalise(Mat M, Vec x) { COREMODAL_PETSC(VecScale(x, 1.0 / std::sqrt(quadratic_form(M, x)))); }

double max_orthonormality_error(Mat M, const std::vector<PetscVector>& X) {
    double worst = 0;
    PetscVector Mx;
    for (size_t j = 0; j < X.size(); ++j) {
        if (j == 0) COREMODAL_PETSC(VecDuplicate(X[0], Mx.out()));
        COREMODAL_PETSC(MatMult(M, X[j], Mx));
        for (size_t i = 0; i <= j; ++i) {
            PetscScalar d;
            COREMODAL_PETSC(VecDot(X[i], Mx, &d));
            worst = std::max(worst, std::abs(d - (i == j ? 1.0 : 0.0)));
        }
    }
    return worst;
}

struct Attempt {
    std::vector<double> lambdas;  // all converged, ascending
    std::vector<PetscVector> vectors;
    int n_converged = 0;
};

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

Attempt run_eps(Mat K, Mat M, double sigma, int nev, const SolveRequest& request) {
    auto eps = configure(K, M, sigma, nev, request);
    const PetscErrorCode solved = EPSSolve(eps);
    if (solved == PETSC_ERR_MAT_CH_ZRPVT || solved == PETSC_ERR_MAT_LU_ZRPVT) throw SolveError(zero_pivot_text(sigma));
    COREMODAL_PETSC(solved);
    return converged_pairs(eps, K);
}

// Below this many unknowns a triangular solve is cheap next to a block's
// dense algebra, and SLEPc's one-vector Krylov-Schur stays (the harmonic
// and beam levels, coarse solid meshes).
constexpr PetscInt kBlockLanczosMinDofs = 20000;

// The block method on the factor's multi-right-hand-side solves
// (block_lanczos.hpp: why): in one process, on a model large enough for the
// pairs wanted (block_lanczos_fits), unless
// the user turned it off (-block_lanczos false) or chose SLEPc's method or
// its factor on the command line (-eps_type, -st_pc_factor_mat_solver_type).
bool block_lanczos_applies(Mat K, PetscInt n_dofs, int wanted) {
    if (mpi_size(PetscObjectComm((PetscObject)K)) != 1 || n_dofs < kBlockLanczosMinDofs ||
        !block_lanczos_fits(n_dofs, wanted))
        return false;
    PetscBool on = PETSC_TRUE, eps_type = PETSC_FALSE, st_factor = PETSC_FALSE;
    COREMODAL_PETSC(PetscOptionsGetBool(nullptr, nullptr, "-block_lanczos", &on, nullptr));
    COREMODAL_PETSC(PetscOptionsHasName(nullptr, nullptr, "-eps_type", &eps_type));
    COREMODAL_PETSC(PetscOptionsHasName(nullptr, nullptr, "-st_pc_factor_mat_solver_type", &st_factor));
    return on && !eps_type && !st_factor;
}

// The Cholesky factor of K - sigma M (sigma < 0: definite) by the package
// shift_invert_factor_package names.
PetscMatrix definite_factor(Mat K, Mat M, double sigma) {
    PetscMatrix A, F;
    COREMODAL_PETSC(MatDuplicate(K, MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -sigma, M, SAME_NONZERO_PATTERN));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    COREMODAL_PETSC(MatGetFactor(A, shift_invert_factor_package(PetscObjectComm((PetscObject)K)), MAT_FACTOR_CHOLESKY,
                                 F.out()));
    PetscIndexSet row_perm, col_perm;
    COREMODAL_PETSC(MatGetOrdering(A, MATORDERINGNATURAL, row_perm.out(), col_perm.out()));
    MatFactorInfo info;
    COREMODAL_PETSC(MatFactorInfoInitialize(&info));
    COREMODAL_PETSC(MatCholeskyFactorSymbolic(F, A, row_perm, &info));
    const PetscErrorCode factored = MatCholeskyFactorNumeric(F, A, &info);
    if (factored == PETSC_ERR_MAT_CH_ZRPVT || factored == PETSC_ERR_MAT_LU_ZRPVT) throw SolveError(zero_pivot_text(sigma));
    COREMODAL_PETSC(factored);
    MatFactorError factor_error;
    COREMODAL_PETSC(MatFactorGetError(F, &factor_error));
    if (factor_error != MAT_FACTOR_NOERROR) throw SolveError(zero_pivot_text(sigma));
    return F;
}

// The lowest nev pairs at the negative shift: block Lanczos where it
// applies, else SLEPc's Krylov-Schur.
Attempt solve_below(Mat K, Mat M, double sigma, int nev, const SolveRequest& request, const Progress& progress) {
    PetscInt n_dofs;
    COREMODAL_PETSC(MatGetSize(K, &n_dofs, nullptr));
    if (!block_lanczos_applies(K, n_dofs, nev)) return run_eps(K, M, sigma, nev, request);
    const PetscMatrix F = definite_factor(K, M, sigma);
    BlockLanczosResult r = block_lanczos_lowest(F, M, sigma, {nev, request.tolerance, request.max_iterations});
    progress("block Lanczos: " + std::to_string(r.blocks_solved) + " passes over the factor with " +
             std::to_string(r.block_size) + " vectors each, " + std::to_string(r.restarts) + " restart(s)");
    Attempt a;
    a.n_converged = static_cast<int>(r.eigenvalues.size());
    a.lambdas = std::move(r.eigenvalues);
    a.vectors = std::move(r.vectors);
    return a;
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
    s << "the shifted factor K - sigma M at sigma = " << sigma << " rad^2/s^2 ("
      << std::sqrt(std::max(sigma, 0.0)) / (2 * M_PI) << " Hz) has " << pivots
      << " negative pivots, but " << found << " modes were found below it: " << pivots - found
      << " mode(s) were missed; raise [analysis] max_iterations or the number of modes";
    return s.str();
}

// |lambda| below this is a rigid-body mode (tolerances.hpp).
double rigid_line(const SolveRequest& r) { return kRigidEigenvalueFraction * r.lambda_scale; }

std::string band_text(const SolveRequest& r) {
    const auto hz = [](double lambda) { return std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI); };
    std::ostringstream s;
    s << "[analysis] band = [" << hz(r.lambda_min.value_or(0.0)) << " Hz, " << hz(*r.lambda_max) << " Hz]";
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

bool in_band(double lambda, const SolveRequest& request) {
    if (!request.lambda_max) return true;
    const double value = std::abs(lambda) < rigid_line(request) ? 0.0 : lambda;
    return value >= request.lambda_min.value_or(0.0) && value <= *request.lambda_max;
}

const char* shift_invert_factor_package(MPI_Comm comm) { return mpi_size(comm) == 1 ? MATSOLVERCHOLMOD : MATSOLVERMUMPS; }

namespace {

long count_below(Mat K, Mat M, double sigma) {
    PetscMatrix A;
    COREMODAL_PETSC(MatDuplicate(K, MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -sigma, M, SAME_NONZERO_PATTERN));
    const std::string what = "K - sigma M at sigma = " + std::to_string(sigma) + " rad^2/s^2";
    return negative_eigenvalue_count(A, what.c_str());
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

// The first n_report modes of a proven-complete attempt, M-normalised, with
// their residuals and the verification.
SolvedModes verified_modes(Mat K, Mat M, Attempt& a, int n_report, double check, long pivots, long found_below) {
    PetscReal K_norm;
    COREMODAL_PETSC(MatNorm(K, NORM_1, &K_norm));
    SolvedModes out;
    for (int i = 0; i < n_report; ++i) {
        m_normalise(M, a.vectors[i]);
        out.relative_residuals.push_back(relative_residual(K, M, K_norm, a.vectors[i], a.lambdas[i]));
        out.eigenvalues.push_back(a.lambdas[i]);
        out.vectors.push_back(std::move(a.vectors[i]));
    }
    auto& v = out.verification;
    v.max_relative_residual = *std::max_element(out.relative_residuals.begin(), out.relative_residuals.end());
    v.max_orthonormality_error = max_orthonormality_error(M, out.vectors);
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

// ---- One factorization for the solve and the count -------------------------
//
// Given a prediction of the lowest eigenvalues (another model of the same
// scene: SolveRequest::predicted_eigenvalues), K - sigma M is factored once,
// by MUMPS's LDL^T, at a shift sigma in the predicted gap above the wanted
// modes. That one factor is SLEPc's shift-and-invert operator, and its
// negative pivots are the number of eigenvalues below sigma (Sylvester):
// when the solve finds exactly that many below sigma, nothing below was
// missed, with no second factorization. The number of solves stays about
// that of the negative shift (case 03: 103 against 115; case 02: 89
// against 80; docs/performance.md, issue 19).

// The prediction may place sigma above this many modes (more than wanted)
// before the pass solves for the wanted ones only and re-shifts to their
// edge (a second factorization): each mode below sigma costs solves.
int most_below_one_shift(int wanted) { return wanted + std::max(kMinExtraModes, wanted / 2); }

// Halfway into the predicted gap after the wanted modes' cluster; none when the
// prediction does not reach past them or the shift would sit among the
// rigid modes (K - sigma M nearly singular there). None either for a free
// body: its rigid modes are one eigenvalue six times over, which a Krylov
// space at a shift far above finds one member at a time (case 01: 198
// solves against 116 with the negative shift, where they come first), so
// the one factor saved no time there.
std::optional<double> predicted_shift(const SolveRequest& r, int wanted) {
    const std::vector<double>& p = r.predicted_eigenvalues;
    if (r.lambda_max || int(p.size()) <= wanted) return std::nullopt;
    if (std::abs(p.front()) < rigid_line(r)) return std::nullopt;
    const int n = reported_count(p, wanted, r.lambda_scale);
    if (n >= int(p.size())) return std::nullopt;
    const double sigma = 0.5 * (p[n - 1] + p[n]);
    if (sigma < kShiftFraction * r.lambda_scale) return std::nullopt;
    return sigma;
}

double hz(double lambda) { return std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI); }

// SLEPc's order of eigenvalues: a before b (res < 0) when lower.
PetscErrorCode lowest_first(PetscScalar ar, PetscScalar, PetscScalar br, PetscScalar, PetscInt* res, void*) {
    const double a = PetscRealPart(ar), b = PetscRealPart(br);
    *res = a < b ? -1 : (a > b ? 1 : 0);
    return 0;
}

// Krylov-Schur with shift-and-invert at sigma on a MUMPS LDL^T factor that
// reports its inertia; the lowest eigenvalues wanted (sigma lies above them).
PetscHandle<EPS, EPSDestroy> configure_ldlt(Mat K, Mat M, double sigma, const SolveRequest& request) {
    PetscHandle<EPS, EPSDestroy> eps = krylov_schur_at(K, M, sigma);
    // The lowest eigenvalues, not those nearest sigma: every one below sigma
    // is wanted, however far below. Shift-and-invert takes only a target or
    // a user's order; SLEPc applies it to the back-transformed values.
    COREMODAL_PETSC(EPSSetEigenvalueComparison(eps, lowest_first, nullptr));
    COREMODAL_PETSC(EPSSetWhichEigenpairs(eps, EPS_WHICH_USER));
    COREMODAL_PETSC(EPSSetTolerances(eps, request.tolerance, request.max_iterations));
    ST st;
    COREMODAL_PETSC(EPSGetST(eps, &st));
    const PC pc = direct_shift_and_invert(st);
    COREMODAL_PETSC(PCSetType(pc, PCCHOLESKY));
    // K - sigma M is indefinite: MUMPS's LDL^T with pivoting, whose inertia
    // is the count. ICNTL(13) = 1 treats the root front like the others: in
    // parallel it keeps it off ScaLAPACK, which would not report the
    // inertia (petsc_algebra.cpp); in one process it measured faster too
    // (case 03: numeric factor 33.9 -> 20.4 s, 103 solves 44.7 -> 32.8 s;
    // docs/performance.md, issue 19). Set through the options database, as
    // the factor is made inside SLEPc's setup; a user's value is kept.
    COREMODAL_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    PetscBool set = PETSC_FALSE;
    COREMODAL_PETSC(PetscOptionsHasName(nullptr, nullptr, "-st_mat_mumps_icntl_13", &set));
    if (!set) COREMODAL_PETSC(PetscOptionsSetValue(nullptr, "-st_mat_mumps_icntl_13", "1"));
    COREMODAL_PETSC(EPSSetFromOptions(eps));
    return eps;
}

// PETSc's words for an error code.
std::string petsc_error_text(PetscErrorCode code) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    return text ? text : "PETSc error " + std::to_string(code);
}

// Sets the solver up (SLEPc factors K - sigma M there) and returns the
// factor's negative pivots: the eigenvalues below sigma. None, with the
// reason said through `progress`, when the factorization failed (sigma on
// an eigenvalue) or the factor gives no inertia (another package chosen
// on the command line).
std::optional<long> factor_and_count(EPS eps, const Progress& progress) {
    const auto failed = [&](const std::string& why) {
        progress("the LDL^T factor at the predicted edge gave no count (" + why + "): solving with a negative shift");
        return std::nullopt;
    };
    if (const PetscErrorCode e = EPSSetUp(eps)) return failed(petsc_error_text(e));
    ST st;
    KSP ksp;
    PC pc;
    Mat F;
    COREMODAL_PETSC(EPSGetST(eps, &st));
    COREMODAL_PETSC(STGetKSP(st, &ksp));
    if (const PetscErrorCode e = KSPSetUp(ksp)) return failed(petsc_error_text(e));
    COREMODAL_PETSC(KSPGetPC(ksp, &pc));
    COREMODAL_PETSC(PCFactorGetMatrix(pc, &F));
    MatFactorError factor_error;
    COREMODAL_PETSC(MatFactorGetError(F, &factor_error));
    if (factor_error != MAT_FACTOR_NOERROR) return failed("a zero pivot: sigma on an eigenvalue");
    PetscInt n_negative = 0;
    if (const PetscErrorCode e = MatGetInertia(F, &n_negative, nullptr, nullptr)) return failed(petsc_error_text(e));
    return n_negative;
}

std::string shift_text(double sigma) {
    std::ostringstream s;
    s << "sigma = " << sigma << " rad^2/s^2, " << hz(sigma) << " Hz";
    return s.str();
}

long count_below_shift(const Attempt& a, double sigma) {
    return std::count_if(a.lambdas.begin(), a.lambdas.end(), [&](double l) { return l < sigma; });
}

// A Krylov space built from one vector holds one direction of each
// eigenspace; the other members of a multiple eigenvalue (the six rigid
// modes of a free body, exact pairs) enter only through round-off, and with
// the shift far above them they may not converge among the lowest. The
// missing ones are the lowest eigenvalues M-orthogonal to those found below
// sigma: SLEPc's deflation space, on the factor already made. Adds those found
// below sigma to `a`, in ascending order.
void add_missed_partners(EPS eps, Mat K, double sigma, long missing, Attempt& a) {
    std::vector<Vec> found;
    for (size_t i = 0; i < a.lambdas.size(); ++i)
        if (a.lambdas[i] < sigma) found.push_back(a.vectors[i]);
    COREMODAL_PETSC(EPSSetDeflationSpace(eps, static_cast<PetscInt>(found.size()), found.data()));
    COREMODAL_PETSC(EPSSetDimensions(eps, static_cast<PetscInt>(missing) + 1, PETSC_DEFAULT, PETSC_DEFAULT));
    COREMODAL_PETSC(EPSSolve(eps));
    Attempt more = converged_pairs(eps, K);
    std::vector<std::pair<double, PetscVector>> all;
    for (size_t i = 0; i < a.lambdas.size(); ++i) all.emplace_back(a.lambdas[i], std::move(a.vectors[i]));
    for (size_t i = 0; i < more.lambdas.size(); ++i)
        if (more.lambdas[i] < sigma) all.emplace_back(more.lambdas[i], std::move(more.vectors[i]));
    std::stable_sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    a.lambdas.clear();
    a.vectors.clear();
    for (auto& [lambda, x] : all) {
        a.lambdas.push_back(lambda);
        a.vectors.push_back(std::move(x));
    }
    a.n_converged += more.n_converged;
}

// What one pass at a shift gave: the modes, proven complete by its own
// factor's count; or where the next pass should factor (the edge of the
// wanted modes found); or neither (the factor failed).
struct ShiftPass {
    std::optional<SolvedModes> modes;
    std::optional<double> next_shift;
};

// Factors K - sigma M once (LDL^T), solves for the lowest modes on that
// factor, and proves them complete by its inertia when sigma lies above
// them and not too far (most_below_one_shift).
ShiftPass solve_at_shift(Mat K, Mat M, const SolveRequest& request, int wanted, double sigma, long n_dofs,
                         const std::string& where, const Progress& progress) {
    progress("factorising K - sigma M (LDL^T) at " + where + ", " + shift_text(sigma) +
             ": one factor for the solve and the count");
    const Heartbeat beat("factorising K - sigma M and solving", progress);
    auto eps = configure_ldlt(K, M, sigma, request);
    const std::optional<long> below = factor_and_count(eps, progress);
    if (!below) return {};
    const bool one_factor = *below >= wanted && *below <= most_below_one_shift(wanted);
    if (!one_factor)
        progress("the shift missed: " + std::to_string(*below) + " eigenvalues below sigma for " +
                 std::to_string(wanted) + " wanted; solving for the lowest modes at this shift to find their edge");
    const int nev = static_cast<int>(std::min<long>(
        n_dofs, one_factor ? *below + 1 : wanted + std::max(kMinExtraModes, wanted / 4)));
    progress("solving for " + std::to_string(nev) + " modes (" + std::to_string(*below) + " below sigma)");
    COREMODAL_PETSC(EPSSetDimensions(eps, nev, PETSC_DEFAULT, PETSC_DEFAULT));
    COREMODAL_PETSC(EPSSolve(eps));
    Attempt a = converged_pairs(eps, K);
    long found_below = count_below_shift(a, sigma);
    // Each round finds at least one member of every eigenspace still missed
    // (one more of the rigid modes, say); a round that finds none ends it.
    for (long before = -1; found_below < *below && found_below > before;) {
        progress("found " + std::to_string(found_below) + " of the " + std::to_string(*below) +
                 " modes below sigma (a multiple eigenvalue's partner, such as a rigid mode): solving again, on the "
                 "same factor, M-orthogonally to those found");
        before = found_below;
        add_missed_partners(eps, K, sigma, *below - found_below, a);
        found_below = count_below_shift(a, sigma);
    }
    const int n_report = reported_count(a.lambdas, wanted, request.lambda_scale);
    if (n_report < wanted) throw SolveError(unconverged_text(a.n_converged, wanted, request));
    if (one_factor && found_below == *below && n_report <= *below)
        return {verified_modes(K, M, a, n_report, sigma, *below, found_below), std::nullopt};
    if (one_factor)
        progress("found " + std::to_string(found_below) + " modes below sigma, where the factor counts " +
                 std::to_string(*below));
    return {std::nullopt, check_point(a.lambdas, n_report, request.lambda_scale)};
}

// The predicted shift, then once the edge the first pass found; none when
// neither proves the modes complete (the caller then takes the negative
// shift and a separate count). Every step is said through `progress`.
constexpr int kShiftPasses = 2;

std::optional<SolvedModes> solve_at_predicted_edge(Mat K, Mat M, const SolveRequest& request, int wanted,
                                                   double sigma, long n_dofs, const Progress& progress) {
    std::string where = "the predicted band edge";
    for (int pass = 0; pass < kShiftPasses; ++pass) {
        ShiftPass p = solve_at_shift(K, M, request, wanted, sigma, n_dofs, where, progress);
        if (p.modes) return std::move(p.modes);
        if (!p.next_shift) return std::nullopt;
        sigma = *p.next_shift;
        where = "the band edge found (re-shifted: a second factorization)";
    }
    progress("no shift near the band edge proved the modes complete: solving with a negative shift");
    return std::nullopt;
}

// The one-factor path with block Lanczos on MUMPS's multi-right-hand-side
// solves (block_lanczos.hpp): one LDL^T factor of K - sigma M at the
// predicted edge counts the eigenvalues below sigma and is the operator
// whose negative Ritz values are those eigenvalues. The modes are proven
// complete when exactly that many are found below sigma. None, said
// through `progress`, when the factor fails, the shift lies below too few
// or above too many modes, or the solve finds another number below it: the
// caller then takes the negative shift and a separate count.
std::optional<SolvedModes> solve_at_edge_in_blocks(Mat K, Mat M, const SolveRequest& request, int wanted, double sigma,
                                                   const Progress& progress) {
    progress("factorising K - sigma M (MUMPS LDL^T) at the predicted band edge, " + shift_text(sigma) +
             ": one factor for the solve (block Lanczos) and the count");
    const Heartbeat beat("factorising K - sigma M and solving", progress);
    PetscMatrix A, F;
    COREMODAL_PETSC(MatDuplicate(K, MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -sigma, M, SAME_NONZERO_PATTERN));
    try {
        F = ldlt_factor(A, "K - sigma M at the predicted band edge");
    } catch (const SolveError& e) {
        progress(std::string("the LDL^T factor at the predicted edge failed (") + e.what() +
                 "): solving with a negative shift");
        return std::nullopt;
    }
    A.reset();
    const long below = negative_pivots(F);
    if (below < wanted || below > most_below_one_shift(wanted)) {
        progress("the shift missed: " + std::to_string(below) + " eigenvalues below sigma for " +
                 std::to_string(wanted) + " wanted; solving with a negative shift");
        return std::nullopt;
    }
    BlockLanczosResult r = block_lanczos_lowest(F, M, sigma, {int(below), request.tolerance, request.max_iterations});
    progress("block Lanczos: " + std::to_string(r.blocks_solved) + " passes over the factor with " +
             std::to_string(r.block_size) + " vectors each, " + std::to_string(r.restarts) + " restart(s)");
    Attempt a;
    a.n_converged = static_cast<int>(r.eigenvalues.size());
    std::vector<std::pair<double, PetscVector>> pairs;
    for (size_t i = 0; i < r.eigenvalues.size(); ++i) pairs.emplace_back(r.eigenvalues[i], std::move(r.vectors[i]));
    std::stable_sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (auto& [lambda, x] : pairs) {
        a.lambdas.push_back(lambda);
        a.vectors.push_back(std::move(x));
    }
    const long found_below = count_below_shift(a, sigma);
    const int n_report = reported_count(a.lambdas, wanted, request.lambda_scale);
    if (found_below == below && n_report >= wanted && n_report <= below)
        return verified_modes(K, M, a, n_report, sigma, below, found_below);
    progress("found " + std::to_string(found_below) + " modes below sigma, where the factor counts " +
             std::to_string(below) + ": solving with a negative shift");
    return std::nullopt;
}

SolvedModes solve_generalized(Mat K, Mat M, const SolveRequest& request, const Progress& progress) {
    PetscInt n_dofs;
    COREMODAL_PETSC(MatGetSize(K, &n_dofs, nullptr));
    const double scale = request.lambda_scale;
    const Wanted w = wanted_modes(K, M, request, n_dofs, progress);
    if (w.empty_band) return SolvedModes{{}, {}, {}, *w.empty_band};
    const int wanted = w.n_modes;
    if (const std::optional<double> edge = predicted_shift(request, wanted)) {
        std::optional<SolvedModes> solved =
            block_lanczos_applies(K, n_dofs, most_below_one_shift(wanted)) ? solve_at_edge_in_blocks(K, M, request, wanted, *edge, progress)
                                             : solve_at_predicted_edge(K, M, request, wanted, *edge, n_dofs, progress);
        if (solved) return std::move(*solved);
    }

    double sigma = -kShiftFraction * scale;
    int nev = std::min<int>(n_dofs, wanted + std::max(kMinExtraModes, wanted / 4));
    for (int attempt = 0;; ++attempt) {
        progress("factorising K - sigma M (" + std::string(shift_invert_factor_package(PetscObjectComm((PetscObject)K))) +
                 " Cholesky, sigma = " + std::to_string(sigma) + ") and solving for " + std::to_string(nev) +
                 " modes (" + (block_lanczos_applies(K, n_dofs, nev) ? "block Lanczos" : "SLEPc Krylov-Schur") +
                 "); MUMPS LDL^T at the band edge for the count");
        Attempt a = [&] {
            const Heartbeat beat("factorising K - sigma M and solving", progress);
            return solve_below(K, M, sigma, nev, request, progress);
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
