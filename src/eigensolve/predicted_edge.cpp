#include "eigensolve/predicted_edge.hpp"

#include "common/error.hpp"
#include "common/heartbeat.hpp"
#include "eigensolve/band_edge.hpp"
#include "eigensolve/block_lanczos.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "eigensolve/shift_invert_steps.hpp"
#include "eigensolve/single_factor.hpp"
#include "eigensolve/single_refinement.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace coremodal::shift_invert {
namespace {

// The prediction may place sigma above this many modes (more than wanted)
// before the pass solves for the wanted ones only and re-shifts to their
// edge (a second factorization): each mode below sigma costs solves.
int most_below_one_shift(int wanted) { return wanted + std::max(kMinExtraModes, wanted / 2); }

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
    // bench/results/log.md, issue 19). Set through the options database, as
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
    s << "sigma = " << sigma << " rad^2/s^2, " << eigenvalue_hz(sigma) << " Hz";
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

std::optional<SolvedModes> solve_at_edge_one_vector(Mat K, Mat M, const SolveRequest& request, int wanted,
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

// What the single-precision pass gave: the modes, proven complete; or
// whether the double factor should be tried (the single one failed or its
// refinement stalled: `why_not` says which), said through `progress`.
struct SinglePass {
    std::optional<SolvedModes> modes;
    bool try_double = true;
    std::string why_not;
};

// The modes with the precision that factored K - sigma M and where their
// count came from, for the run's summary, console and report.
SolvedModes with_precision(SolvedModes s, const FactorPrecision& p, const std::string& used, const std::string& count) {
    s.verification.factor_precision = FactorPrecisionUsed{used, p.asked, p.why, count};
    return s;
}

// "; " and how block Lanczos's predicted start was dropped, or nothing: what
// the summary's solver line adds after the count.
std::string start_note(const Attempt& a) { return a.start_dropped.empty() ? "" : "; " + a.start_dropped; }

std::string scientific(double x) {
    std::ostringstream s;
    s.precision(2);
    s << std::scientific << x;
    return s.str();
}

// Block Lanczos on the single factor's solves refined to the pass error,
// the pairs then cleaned in double (single_refinement.hpp) and the work said
// through `progress`; RefinementStalled when a refinement stalled or block
// Lanczos did not converge in kMaxSingleRestarts (the caller takes the
// double factor).
Attempt single_factor_pairs(SingleLdlt& F, Mat K, Mat M, double sigma, long below, const SolveRequest& request,
                            const Progress& progress) {
    const double pass_error = pass_backward_error();
    SolveRequest loose = request;
    loose.tolerance = std::max(request.tolerance, single_lanczos_tolerance());
    loose.max_iterations = std::min(request.max_iterations, kMaxSingleRestarts);
    Attempt a = block_lanczos_attempt(
        [&](int cols, const double* in, double* out) { F.solve(cols, in, out, pass_error); }, M, sigma, int(below),
        loose, progress);
    if (a.n_converged < below)
        throw RefinementStalled("block Lanczos on the single factor's refined solves converged " +
                                std::to_string(a.n_converged) + " of " + std::to_string(below) + " pairs in " +
                                std::to_string(loose.max_iterations) + " restarts (the double factor's need 1 or 2)");
    const int ritz_steps = refine_pairs_in_double(F, K, M, a.lambdas, a.vectors);
    progress("single-precision factor: " + std::to_string(F.solves()) + " block solves refined in double to a "
             "backward error below " + scientific(pass_error) + " (at most " + std::to_string(F.most_steps()) +
             " solve(s) each), " + std::to_string(ritz_steps) +
             " Rayleigh-Ritz step(s) with the double K and M on a solve refined below " +
             scientific(kRefinedBackwardError) + "; " + std::to_string(F.factor_passes()) +
             " passes over the factor in all");
    return a;
}

// The single factor's modes with their count: its own inertia when the
// verified modes prove it (single_count_proven), else a double LDL^T's of
// A = K - sigma M; none, said through `progress`, when that disagrees.
SinglePass counted_single_modes(const SingleLdlt& F, Mat A, Mat K, Mat M, Attempt& a, double sigma, long below,
                                int n_report, const FactorPrecision& precision, const Progress& progress) {
    const long found_below = count_below_shift(a, sigma);
    const std::string margin = "no eigenvalue of K - sigma M within " + scientific(count_margin(F)) +
                               " (10 x the factor's backward error " + scientific(F.factor_backward_error()) +
                               " x ||K - sigma M||_1) of zero";
    if (found_below == below && single_count_proven(F, M, sigma, a.lambdas, a.vectors)) {
        progress("count from the single-precision factor's inertia, proven: " + margin +
                 " (docs/theory/methods.md, \"A count from a single-precision factor\")");
        return {with_precision(verified_modes(K, M, a, n_report, sigma, below, found_below), precision, "single",
                               "the single-precision factor's inertia, proven: " + margin + start_note(a)),
                false, {}};
    }
    progress("the single-precision factor's count (" + std::to_string(below) + " below sigma, " +
             std::to_string(found_below) + " found) is not proven (" + margin +
             " fails): counting with the double-precision LDL^T");
    long double_below = 0;
    try {
        double_below = negative_eigenvalue_count(A, "K - sigma M at the predicted band edge");
    } catch (const SolveError& e) {
        progress(std::string(e.what()) + ": solving with a negative shift");
        return {std::nullopt, false, {}};
    }
    if (double_below == found_below)
        return {with_precision(verified_modes(K, M, a, n_report, sigma, double_below, found_below), precision,
                               "single",
                               "the double-precision factor's inertia: the single one's was not proven (" + margin +
                                   " fails)" + start_note(a)),
                false, {}};
    progress("found " + std::to_string(found_below) + " modes below sigma, where the double factor counts " +
             std::to_string(double_below) + ": solving with a negative shift");
    return {std::nullopt, false, {}};
}

// The one-factor path on the single-precision LDL^T (single_factor.hpp):
// block Lanczos on its refined solves, the count from its inertia when the
// modes found prove it (single_count_proven), else from a double LDL^T.
SinglePass solve_at_edge_single(Mat K, Mat M, const SolveRequest& request, int wanted, double sigma,
                                const FactorPrecision& precision, const Progress& progress) {
    const PetscMatrix A = shifted(K, M, sigma);
    std::optional<SingleLdlt> F;
    try {
        F.emplace(A);
    } catch (const SolveError& e) {
        progress(std::string(e.what()) + ": the double-precision factor instead");
        return {std::nullopt, true, e.what()};
    }
    if (F->out_of_core())
        progress("the single-precision factor is kept on disk (MUMPS out of core: its analysis estimated " +
                 std::to_string(F->estimate_mb()) + " MB; petsc_algebra.hpp, kInCoreShare)");
    const long below = F->negative_pivots();
    if (below < wanted || below > most_below_one_shift(wanted)) {
        progress("the shift missed: " + std::to_string(below) + " eigenvalues below sigma for " +
                 std::to_string(wanted) + " wanted; solving with a negative shift");
        return {std::nullopt, false, {}};
    }
    Attempt a;
    try {
        a = single_factor_pairs(*F, K, M, sigma, below, request, progress);
    } catch (const RefinementStalled& e) {
        progress(std::string(e.what()) + ": falling back to the double-precision factor");
        return {std::nullopt, true, e.what()};
    }
    const long found_below = count_below_shift(a, sigma);
    const int n_report = reported_count(a.lambdas, wanted, request.lambda_scale);
    if (n_report < wanted || n_report > found_below) {
        progress("found " + std::to_string(found_below) + " modes below sigma for " + std::to_string(wanted) +
                 " wanted: solving with a negative shift");
        return {std::nullopt, false, {}};
    }
    return counted_single_modes(*F, A, K, M, a, sigma, below, n_report, precision, progress);
}

// The one-factor path with block Lanczos on MUMPS's multi-right-hand-side
// solves (block_lanczos.hpp): one LDL^T factor of K - sigma M at the
// predicted edge counts the eigenvalues below sigma and is the operator
// whose negative Ritz values are those eigenvalues. The modes are proven
// complete when exactly that many are found below sigma. None, said
// through `progress`, when the factor fails, the shift lies below too few
// or above too many modes, or the solve finds another number below it: the
// caller then takes the negative shift and a separate count. In one
// process the factor is single precision unless the user asks for double
// (factor_precision_choice); the double one when the single one fails.
std::optional<SolvedModes> solve_at_edge_in_blocks(Mat K, Mat M, const SolveRequest& request, int wanted, double sigma,
                                                   const Progress& progress) {
    const FactorPrecision precision = factor_precision_choice(PetscObjectComm((PetscObject)K));
    progress("factorising K - sigma M (MUMPS LDL^T, " + precision.why + ") at the predicted band edge, " +
             shift_text(sigma) + ": one factor for the solve (block Lanczos) and the count");
    const Heartbeat beat("factorising K - sigma M and solving", progress);
    std::string fell_back;
    if (precision.single) {
        SinglePass p = solve_at_edge_single(K, M, request, wanted, sigma, precision, progress);
        if (p.modes || !p.try_double) return std::move(p.modes);
        progress("factorising K - sigma M in double precision (MUMPS LDL^T) at the predicted band edge");
        fell_back = "; fell back to double: " + p.why_not;
    }
    PetscMatrix F;
    try {
        F = ldlt_factor(shifted(K, M, sigma), "K - sigma M at the predicted band edge");
    } catch (const SolveError& e) {
        progress(std::string("the LDL^T factor at the predicted edge failed (") + e.what() +
                 "): solving with a negative shift");
        return std::nullopt;
    }
    say_if_out_of_core(F, progress);
    const long below = negative_pivots(F);
    if (below < wanted || below > most_below_one_shift(wanted)) {
        progress("the shift missed: " + std::to_string(below) + " eigenvalues below sigma for " +
                 std::to_string(wanted) + " wanted; solving with a negative shift");
        return std::nullopt;
    }
    Attempt a = block_lanczos_attempt(F, M, sigma, int(below), request, progress);
    const long found_below = count_below_shift(a, sigma);
    const int n_report = reported_count(a.lambdas, wanted, request.lambda_scale);
    if (found_below == below && n_report >= wanted && n_report <= below)
        return with_precision(verified_modes(K, M, a, n_report, sigma, below, found_below), precision, "double",
                              "the double-precision factor's inertia" + fell_back + start_note(a));
    progress("found " + std::to_string(found_below) + " modes below sigma, where the factor counts " +
             std::to_string(below) + ": solving with a negative shift");
    return std::nullopt;
}

}  // namespace

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

std::optional<SolvedModes> solve_at_predicted_edge(Mat K, Mat M, const SolveRequest& request, int wanted,
                                                   double sigma, long n_dofs, const Progress& progress) {
    return block_lanczos_applies(n_dofs, most_below_one_shift(wanted))
               ? solve_at_edge_in_blocks(K, M, request, wanted, sigma, progress)
               : solve_at_edge_one_vector(K, M, request, wanted, sigma, n_dofs, progress);
}

}  // namespace coremodal::shift_invert
