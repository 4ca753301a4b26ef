#include "eigensolve/gyroscopic_solver.hpp"

#include "eigensolve/band_edge.hpp"
#include "common/blas_threads.hpp"
#include "common/error.hpp"
#include "common/heartbeat.hpp"
#include "eigensolve/petsc_algebra.hpp"

#include <slepcpep.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

namespace coremodal {
namespace {

// Extra eigenvalues computed beyond the wanted ones, as in modal_solver.cpp:
// they locate the gap for the count and catch a partner of the last mode.
constexpr int kMinExtraModes = 4;
// The targets (times the first) of further tries after LAPACK refused to
// reorder TOAR's Schur form (run_pep): far enough from the first to change
// the projected problem.
constexpr double kRetryTargetFactors[] = {0.3, 2.5, 0.1};
constexpr int kMaxTargetRetries = 2;
// A reported mode whose relative residual exceeds this did not converge
// (SLEPc's own test runs on the linearization): an error, never a number.
constexpr double kMaxAcceptedResidual = 1e-6;

using Pep = PetscHandle<PEP, PEPDestroy>;

// K (with any geometric stiffness and Omega^2 K_Omega), C = Omega G (zero without a gyroscopic
// term), M, and the 1-norms the residuals are scaled by.
struct SpinningOperators {
    EffectiveStiffness stiffness;
    PetscMatrix C;
    Mat K, M;
    double norm_K = 0, norm_C = 0, norm_M = 0;

    SpinningOperators(const OperatorSet& ops, double spin) : stiffness(ops, spin), K(stiffness.get()), M(ops.M()) {
        if (ops.has(Term::gyroscopic)) {
            COREMODAL_PETSC(MatDuplicate(ops[Term::gyroscopic], MAT_COPY_VALUES, C.out()));
            COREMODAL_PETSC(MatScale(C, spin));
        } else {
            COREMODAL_PETSC(MatDuplicate(M, MAT_DO_NOT_COPY_VALUES, C.out()));
            COREMODAL_PETSC(MatZeroEntries(C));
        }
        PetscReal n;
        COREMODAL_PETSC(MatNorm(K, NORM_1, &n));
        norm_K = n;
        COREMODAL_PETSC(MatNorm(C, NORM_1, &n));
        norm_C = n;
        COREMODAL_PETSC(MatNorm(M, NORM_1, &n));
        norm_M = n;
    }
};

// neg Q(omega) of the real symmetric form [[A, -B], [B, A]], A = K - omega^2 M,
// B = omega C: twice the Hermitian Q's count (header).
long embedded_negative_count(const SpinningOperators& op, double omega) {
    PetscMatrix A, B, minus_B, nest, S;
    COREMODAL_PETSC(MatDuplicate(op.K, MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -omega * omega, op.M, DIFFERENT_NONZERO_PATTERN));
    COREMODAL_PETSC(MatDuplicate(op.C, MAT_COPY_VALUES, B.out()));
    COREMODAL_PETSC(MatScale(B, omega));
    COREMODAL_PETSC(MatDuplicate(B, MAT_COPY_VALUES, minus_B.out()));
    COREMODAL_PETSC(MatScale(minus_B, -1.0));
    Mat blocks[4] = {A, minus_B, B, A};
    COREMODAL_PETSC(MatCreateNest(PetscObjectComm((PetscObject)op.K), 2, nullptr, 2, nullptr, blocks, nest.out()));
    COREMODAL_PETSC(MatConvert(nest, MATAIJ, MAT_INITIAL_MATRIX, S.out()));
    const std::string what = "Q(omega) at omega = " + std::to_string(omega) + " rad/s";
    return negative_eigenvalue_count(S, what.c_str());
}

// How P(tau) is factored: PETSc's own LU in a quotient minimum degree
// ordering, or MUMPS (in parallel, and if the first ever meets a zero pivot).
enum class Factor { petsc_qmd, mumps };

Pep configure(const SpinningOperators& op, double tau, int nev, const SolveRequest& request, Factor factor) {
    Pep pep;
    COREMODAL_PETSC(PEPCreate(PetscObjectComm((PetscObject)op.K), pep.out()));
    Mat A[3] = {op.K, op.C.get(), op.M};
    COREMODAL_PETSC(PEPSetOperators(pep, 3, A));
    COREMODAL_PETSC(PEPSetProblemType(pep, PEP_GENERAL));
    COREMODAL_PETSC(PEPSetType(pep, PEPTOAR));
    COREMODAL_PETSC(PEPSetTarget(pep, tau));
    COREMODAL_PETSC(PEPSetWhichEigenpairs(pep, PEP_TARGET_MAGNITUDE));
    COREMODAL_PETSC(PEPSetDimensions(pep, nev, PETSC_DEFAULT, PETSC_DEFAULT));
    COREMODAL_PETSC(PEPSetTolerances(pep, request.tolerance, request.max_iterations));
    // The eigenvector is read off the linearization's by the smallest
    // residual: the default (the block of larger norm) returned rigid modes
    // (lambda ~ 1e-14) with relative residuals of 0.5 on a free spinning body.
    COREMODAL_PETSC(PEPSetExtract(pep, PEP_EXTRACT_RESIDUAL));
    // Scale lambda by sqrt(||K|| / ||M||) (Fan, Lin and Van Dooren): without
    // it TOAR reported eigenvalues off the imaginary axis by 1.5 % as
    // converged on a harmonic of a steel tube, ||K|| / ||M|| ~ 1e9.
    COREMODAL_PETSC(PEPSetScale(pep, PEP_SCALE_SCALAR, PETSC_DEFAULT, nullptr, nullptr, PETSC_DEFAULT, PETSC_DEFAULT));
    ST st;
    COREMODAL_PETSC(PEPGetST(pep, &st));
    const PC pc = direct_shift_and_invert(st);
    // P(tau) = K + tau C + tau^2 M is not symmetric (C is skew): an LU factor.
    // Its symmetric part K + tau^2 M is positive definite, so every leading
    // minor is nonzero and LU needs no pivoting. PETSc's own LU in a QMD
    // ordering: on the two coupled families of a harmonic its triangular
    // solves took 0.62 s where MUMPS's (PORD) took 18 s and PETSc's in
    // nested dissection 0.97 s (case 12 at the harmonic level, 3 speeds,
    // -log_view; nested dissection and RCM also met spurious zero pivots on
    // the small rotors of the unit tests).
    COREMODAL_PETSC(PCSetType(pc, PCLU));
    if (factor == Factor::petsc_qmd) {
        COREMODAL_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERPETSC));
        COREMODAL_PETSC(PCFactorSetMatOrderingType(pc, MATORDERINGQMD));
    } else {
        COREMODAL_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    }
    COREMODAL_PETSC(PEPSetFromOptions(pep));
    return pep;
}

struct Candidate {
    double omega = 0;
    PetscVector real, imag;
};

// Every converged eigenpair with Im lambda >= 0 (the conjugate of each
// complex pair dropped; a real eigenvalue, which round-off makes of a rigid
// mode's 0, kept when it is not negative), ascending in omega = |lambda|.
std::vector<Candidate> run_pep(const SpinningOperators& op, double tau, int nev, const SolveRequest& request,
                               int& n_converged) {
    const bool serial = mpi_size(PetscObjectComm((PetscObject)op.K)) == 1;
    Pep pep = configure(op, tau, nev, request, serial ? Factor::petsc_qmd : Factor::mumps);
    {
        const SingleThreadBlas one_thread;  // common/blas_threads.hpp: why
        PetscErrorCode solved = PEPSolve(pep);
        if (solved == PETSC_ERR_MAT_LU_ZRPVT && serial) {
            pep = configure(op, tau, nev, request, Factor::mumps);
            solved = PEPSolve(pep);
        }
        // LAPACK's trexc may refuse to reorder the Schur form of TOAR's
        // projected problem ("Error in LAPACK subroutine trexc: info=1") when
        // a cluster there is defective: a free body's rigid modes at rest are
        // double zeros of the quadratic problem with Jordan blocks, six of
        // them in a free solid (a free ring at the solid level met it on
        // 2 x 96 x 2 and 1 x 128 x 1 cells, not on 2 x 64 x 2 or 2 x 128 x 2).
        // Another target changes the projected problem, and the lowest modes
        // stay the nearest (header).
        for (double factor : kRetryTargetFactors) {
            if (solved != PETSC_ERR_LIB) break;
            pep = configure(op, tau * factor, nev, request, serial ? Factor::petsc_qmd : Factor::mumps);
            solved = PEPSolve(pep);
        }
        COREMODAL_PETSC(solved);
    }
    PetscInt nconv;
    COREMODAL_PETSC(PEPGetConverged(pep, &nconv));
    n_converged = int(nconv);
    std::vector<Candidate> out;
    for (PetscInt i = 0; i < nconv; ++i) {
        PetscScalar kr, ki;
        Candidate c;
        COREMODAL_PETSC(MatCreateVecs(op.K, c.real.out(), nullptr));
        COREMODAL_PETSC(VecDuplicate(c.real, c.imag.out()));
        COREMODAL_PETSC(PEPGetEigenpair(pep, i, &kr, &ki, c.real, c.imag));
        if (ki < 0 || (ki == 0 && kr < 0)) continue;
        c.omega = std::hypot(double(kr), double(ki));
        out.push_back(std::move(c));
    }
    std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) { return a.omega < b.omega; });
    return out;
}

// x^H A x split into its real and imaginary parts, for real A and x = a + i b
// against y = c + i d: y^H A x = c^T A a + d^T A b + i (c^T A b - d^T A a).
std::complex<double> hermitian_form(Mat A, Vec c, Vec d, Vec a, Vec b) {
    return {bilinear_form(A, c, a) + bilinear_form(A, d, b), bilinear_form(A, c, b) - bilinear_form(A, d, a)};
}

double relative_residual(const SpinningOperators& op, const Candidate& c) {
    // Q x = (K - w^2 M) x + i w C x: real part (K - w^2 M) a - w C b, imaginary (K - w^2 M) b + w C a.
    const double w = c.omega;
    auto part = [&](Vec u, Vec v, double sign) {
        PetscVector r, t;
        COREMODAL_PETSC(VecDuplicate(u, r.out()));
        COREMODAL_PETSC(VecDuplicate(u, t.out()));
        COREMODAL_PETSC(MatMult(op.K, u, r));
        COREMODAL_PETSC(MatMult(op.M, u, t));
        COREMODAL_PETSC(VecAXPY(r, -w * w, t));
        COREMODAL_PETSC(MatMult(op.C, v, t));
        COREMODAL_PETSC(VecAXPY(r, sign * w, t));
        return vector_norm(r);
    };
    const double residual = std::hypot(part(c.real, c.imag, -1.0), part(c.imag, c.real, +1.0));
    const double x_norm = std::hypot(vector_norm(c.real), vector_norm(c.imag));
    return residual / ((op.norm_K + w * op.norm_C + w * w * op.norm_M) * x_norm);
}

void m_normalise(Mat M, Candidate& c) {
    const double scale = 1.0 / std::sqrt(quadratic_form(M, c.real) + quadratic_form(M, c.imag));
    COREMODAL_PETSC(VecScale(c.real, scale));
    COREMODAL_PETSC(VecScale(c.imag, scale));
}

// x_j^H ((w_i + w_j) M - i C) x_i, normalised by the modes' own norms in that
// product, over elastic modes of distinct frequency (header).
double max_orthogonality_error(const SpinningOperators& op, const std::vector<GyroscopicMode>& modes,
                               double rigid_omega) {
    const auto product = [&](const GyroscopicMode& j, const GyroscopicMode& i) {
        const std::complex<double> m = hermitian_form(op.M, j.real, j.imag, i.real, i.imag);
        const std::complex<double> c = hermitian_form(op.C, j.real, j.imag, i.real, i.imag);
        return (i.omega + j.omega) * m - std::complex<double>(0, 1) * c;
    };
    std::vector<double> norm(modes.size());
    for (size_t i = 0; i < modes.size(); ++i) norm[i] = std::abs(product(modes[i], modes[i]));
    double worst = 0;
    for (size_t i = 0; i < modes.size(); ++i)
        for (size_t j = 0; j < i; ++j) {
            const double wi = modes[i].omega, wj = modes[j].omega;
            if (wj < rigid_omega || (wi * wi - wj * wj) <= kClusterTolerance * wi * wi) continue;
            worst = std::max(worst, std::abs(product(modes[j], modes[i])) / std::sqrt(norm[i] * norm[j]));
        }
    return worst;
}

// The eigenvalues omega^2 of the candidates, ascending as they are: what
// eigensolve/band_edge.hpp's report and count rule reads.
std::vector<double> squared_omegas(const std::vector<Candidate>& c) {
    std::vector<double> lambdas;
    for (const Candidate& x : c) lambdas.push_back(x.omega * x.omega);
    return lambdas;
}

GyroscopicModes verified(const SpinningOperators& op, std::vector<Candidate>& c, int n_report, double rigid_omega,
                         double check, long counted) {
    GyroscopicModes out;
    for (int i = 0; i < n_report; ++i) {
        m_normalise(op.M, c[i]);
        GyroscopicMode m;
        m.omega = c[i].omega;
        m.relative_residual = relative_residual(op, c[i]);
        m.real = std::move(c[i].real);
        m.imag = std::move(c[i].imag);
        out.modes.push_back(std::move(m));
    }
    auto& v = out.verification;
    for (const auto& m : out.modes) v.max_relative_residual = std::max(v.max_relative_residual, m.relative_residual);
    v.max_orthonormality_error = max_orthogonality_error(op, out.modes, rigid_omega);
    v.check_shift = check * check;
    v.negative_pivots_at_shift = counted;
    v.modes_below_shift = counted;
    v.complete = true;
    return out;
}

std::string count_mismatch_text(long counted, long found, double check) {
    std::ostringstream s;
    s << "the inertia of Q(omega) at omega = " << check << " rad/s (" << check / (2 * M_PI) << " Hz) counts "
      << counted << " modes of the spinning structure above the rigid line and below it, but " << found
      << " were found: raise [analysis] max_iterations or the number of modes";
    return s.str();
}

std::string rigid_mismatch_text(long counted, long found) {
    return "the inertia of Q(omega) at the rigid line counts " + std::to_string(counted) +
           " rigid modes of the spinning structure, but the quadratic solver found " + std::to_string(found) +
           ": raise [analysis] max_iterations or the number of modes";
}

// neg(K(Omega) + omega_0^2 M): the stiffness the count assumes (header).
long stiffness_negative_count(const SpinningOperators& op, double rigid_omega) {
    PetscMatrix A;
    COREMODAL_PETSC(MatDuplicate(op.K, MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, rigid_omega * rigid_omega, op.M, DIFFERENT_NONZERO_PATTERN));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    return negative_eigenvalue_count(A, "the effective stiffness K(Omega) + omega_0^2 M");
}

}  // namespace

std::string indefinite_stiffness_text(double spin, long n_negative) {
    std::ostringstream s;
    s << "at " << spin * 60 / (2 * M_PI) << " rpm (" << spin / (2 * M_PI)
      << " Hz) the stiffness at speed, K + Omega^2 K_Omega (the centrifugal prestress, less the spin "
         "softening), is indefinite: an inertia count finds "
      << n_negative << " direction" << (n_negative == 1 ? "" : "s")
      << " softer than the rigid line. The gyroscopic solver's completeness count assumes it is not "
         "(every mode must cross the count's zero downwards), so no modes are reported at this speed. "
         "In co-rotating coordinates (segmented chucks at the solid level) this is what happens above the "
         "first forward critical speed of order 1, where that whirl's frequency in the rotating frame has "
         "passed through zero; in the stationary frame, a centrifugal softening stronger than the structure. "
         "End the [rotation] speeds below this speed, or, for a body of revolution, spin it in the "
         "stationary frame (model = \"harmonic\"), where the stiffness stays definite until the centrifugal "
         "softening outgrows it";
    return s.str();
}

namespace {

// neg Q(omega_0) / 2, the modes below the rigid line, after the count's
// premise K(Omega) + omega_0^2 M >= 0: free where nothing is below the
// rigid line (header), one count of the set's size otherwise.
long modes_below_rigid_line(const SpinningOperators& op, double spin, double rigid_omega) {
    const long below_rigid = embedded_negative_count(op, rigid_omega) / 2;
    if (below_rigid > 0 && spin > 0) {
        const long soft = stiffness_negative_count(op, rigid_omega);
        if (soft > 0) throw SolveError(indefinite_stiffness_text(spin, soft));
    }
    return below_rigid;
}

// The verified modes, refused when a residual exceeds what the solver accepts.
GyroscopicModes converged(GyroscopicModes out) {
    if (out.verification.max_relative_residual > kMaxAcceptedResidual)
        throw SolveError("the quadratic problem's modes did not converge: largest relative residual " +
                         std::to_string(out.verification.max_relative_residual) +
                         "; raise [analysis] max_iterations or lower [analysis] tolerance");
    return out;
}

}  // namespace

double gyroscopic_rigid_omega(const SolveRequest& request) {
    return kQuadraticRigidFrequencyFraction * std::sqrt(request.lambda_scale);
}

long count_gyroscopic_below(const OperatorSet& operators, double spin, double omega) {
    return embedded_negative_count(SpinningOperators(operators, spin), omega) / 2;
}

GyroscopicModes solve_gyroscopic(const OperatorSet& operators, double spin, const SolveRequest& request,
                                 const Progress& progress) {
    if (operators.has(Term::damping) || operators.has(Term::imaginary_stiffness))
        throw SolveError("the operator set has a damping term: a quadratic problem without the Hermitian structure "
                         "the gyroscopic solver's completeness count needs; not supported yet");
    if (request.lambda_max)
        throw InputError("a band ([analysis] band) is not supported for a spinning scene yet; ask for the lowest "
                         "modes ([analysis] modes)");
    const SpinningOperators op(operators, spin);
    PetscInt n_dofs;
    COREMODAL_PETSC(MatGetSize(op.K, &n_dofs, nullptr));
    const double scale = request.lambda_scale;
    const double tau = kTargetFraction * std::sqrt(scale);
    const double rigid_omega = gyroscopic_rigid_omega(request);
    const int wanted = std::min<int>(request.n_modes, n_dofs);
    int nev = std::min<int>(2 * n_dofs, 2 * (wanted + std::max(kMinExtraModes, wanted / 4)));
    const long below_rigid = modes_below_rigid_line(op, spin, rigid_omega);
    for (int attempt = 0;; ++attempt) {
        progress("factorising P(tau) = K + tau Omega G + tau^2 M and solving the quadratic problem for " +
                 std::to_string(nev) + " eigenvalues");
        int n_converged = 0;
        std::vector<Candidate> c = [&] {
            const Heartbeat beat("solving the quadratic problem", progress);
            return run_pep(op, tau, nev, request, n_converged);
        }();
        const std::vector<double> lambdas = squared_omegas(c);
        const int n_report = reported_count(lambdas, wanted, scale);
        if (n_report < wanted)
            throw SolveError("converged " + std::to_string(n_converged) + " eigenvalues of the quadratic problem, " +
                             std::to_string(n_report) + " of the " + std::to_string(wanted) +
                             " modes requested; raise [analysis] max_iterations");
        const double check = std::sqrt(check_point(lambdas, n_report, scale));
        progress("checking completeness: inertia of Q(omega) at the band edge");
        const long counted = embedded_negative_count(op, check) / 2 - below_rigid;
        const long found = std::count_if(c.begin(), c.begin() + n_report,
                                         [&](const Candidate& x) { return x.omega >= rigid_omega; });
        // The rigid modes are reported, not counted against the band edge,
        // but below_rigid says how many there are: a solver that lost one
        // (a double zero is defective, and TOAR converges it or not by the
        // machine's round-off) would shift every mode after it.
        const long rigid_found = n_report - found;
        const bool rigid_complete = rigid_found >= std::min<long>(below_rigid, wanted);
        if (counted == found && rigid_complete) return converged(verified(op, c, n_report, rigid_omega, check, counted));
        if (!rigid_complete) {
            if (attempt >= kMaxTargetRetries) throw SolveError(rigid_mismatch_text(below_rigid, rigid_found));
            progress("the inertia says " + std::to_string(below_rigid) + " rigid modes, " +
                     std::to_string(rigid_found) + " found: solving again with a larger subspace");
            nev = std::min<int>(2 * n_dofs, nev + 2 * (int(below_rigid - rigid_found) + kMinExtraModes));
            continue;
        }
        if (attempt >= kMaxTargetRetries || counted < found)
            throw SolveError(count_mismatch_text(counted, found, check));
        progress("the count says " + std::to_string(counted) + " modes, " + std::to_string(found) +
                 " found: solving again with a larger subspace");
        nev = std::min<int>(2 * n_dofs, 2 * (int(counted) + n_report - int(found) + kMinExtraModes + wanted / 4));
    }
}

}  // namespace coremodal
