#include "eigensolve/zero_frequency_speeds.hpp"

#include "common/error.hpp"
#include "eigensolve/modal_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "eigensolve/projection_basis.hpp"  // norm_1

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace coremodal {
namespace {

// A pencil eigenpair whose relative residual exceeds this is not accepted:
// the symmetric solver's own bound for reported modes (modal_solver.cpp).
constexpr double kMaxPencilResidual = 1e-8;
// Eigenvalues computed beyond those counted: they show the gap above the
// last one and catch a degenerate partner.
constexpr int kExtraEigenvalues = 4;
// Tries with more eigenvalues when fewer than counted converged.
constexpr int kMaxTries = 3;

using Eps = PetscHandle<EPS, EPSDestroy>;

// The pencil's matrices: K (at rest, with any prestress of the set) and
// B = -K_Omega; the 1-norms that scale the residuals.
struct Pencil {
    EffectiveStiffness stiffness;
    PetscMatrix B;
    double norm_K = 0, norm_B = 0;

    explicit Pencil(const OperatorSet& ops) : stiffness(ops, 0.0) {
        COREMODAL_PETSC(MatDuplicate(ops[Term::centrifugal], MAT_COPY_VALUES, B.out()));
        COREMODAL_PETSC(MatScale(B, -1.0));
        COREMODAL_PETSC(MatSetOption(B, MAT_SYMMETRIC, PETSC_TRUE));
        norm_K = norm_1(stiffness.get());
        norm_B = norm_1(B);
    }
    Mat K() const { return stiffness.get(); }
};

// neg(K + s K_Omega) = neg(K - s B).
long negative_count(const Pencil& p, double s, const char* what) {
    PetscMatrix A;
    COREMODAL_PETSC(MatDuplicate(p.K(), MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -s, p.B, DIFFERENT_NONZERO_PATTERN));
    return negative_eigenvalue_count(A, what);
}

// The count's premise: K positive definite, i.e. no eigenvalue of
// K x = lambda M x below the rigid line (a held structure).
void require_held(const OperatorSet& ops, const Pencil& p, double rigid_omega) {
    PetscMatrix A;
    COREMODAL_PETSC(MatDuplicate(p.K(), MAT_COPY_VALUES, A.out()));
    COREMODAL_PETSC(MatAXPY(A, -rigid_omega * rigid_omega, ops.M(), DIFFERENT_NONZERO_PATTERN));
    const long rigid = negative_eigenvalue_count(A, "K - omega_0^2 M");
    if (rigid > 0)
        throw SolveError("the speeds of zero rotating-frame frequency need a held structure (K positive definite), "
                         "but K has " + std::to_string(rigid) + " mode" + (rigid == 1 ? "" : "s") +
                         " below the rigid line (a free body): its rigid motions have zero frequency at every speed");
}

// B x = c K x, the largest c (c = 1/Omega^2), K factored once by Cholesky.
Eps configure(const Pencil& p, int nev, const SolveRequest& request) {
    Eps eps;
    COREMODAL_PETSC(EPSCreate(PetscObjectComm((PetscObject)p.K()), eps.out()));
    COREMODAL_PETSC(EPSSetOperators(eps, p.B, p.K()));
    COREMODAL_PETSC(EPSSetProblemType(eps, EPS_GHEP));
    COREMODAL_PETSC(EPSSetType(eps, EPSKRYLOVSCHUR));
    COREMODAL_PETSC(EPSSetWhichEigenpairs(eps, EPS_LARGEST_REAL));
    COREMODAL_PETSC(EPSSetDimensions(eps, nev, PETSC_DEFAULT, PETSC_DEFAULT));
    COREMODAL_PETSC(EPSSetTolerances(eps, request.tolerance, request.max_iterations));
    ST st;
    COREMODAL_PETSC(EPSGetST(eps, &st));
    COREMODAL_PETSC(STSetType(st, STSHIFT));  // operator K^-1 B: a solve with K, no shift
    KSP ksp;
    PC pc;
    COREMODAL_PETSC(STGetKSP(st, &ksp));
    COREMODAL_PETSC(KSPSetType(ksp, KSPPREONLY));
    COREMODAL_PETSC(KSPGetPC(ksp, &pc));
    COREMODAL_PETSC(PCSetType(pc, PCCHOLESKY));
    COREMODAL_PETSC(PCFactorSetMatSolverType(pc, shift_invert_factor_package(PetscObjectComm((PetscObject)p.K()))));
    COREMODAL_PETSC(EPSSetOptionsPrefix(eps, "pencil_"));  // -pencil_eps_*, -pencil_st_* for experts
    COREMODAL_PETSC(EPSSetFromOptions(eps));
    return eps;
}

double residual(const Pencil& p, double mu, Vec x) {
    PetscVector Kx, Bx;
    COREMODAL_PETSC(VecDuplicate(x, Kx.out()));
    COREMODAL_PETSC(VecDuplicate(x, Bx.out()));
    COREMODAL_PETSC(MatMult(p.K(), x, Kx));
    COREMODAL_PETSC(MatMult(p.B, x, Bx));
    COREMODAL_PETSC(VecAXPY(Kx, -mu, Bx));
    return vector_norm(Kx) / ((p.norm_K + mu * p.norm_B) * vector_norm(x));
}

// The converged pairs with Omega^2 = 1/c below max_spin^2, ascending in Omega.
std::vector<ZeroFrequencySpeed> below(EPS eps, const Pencil& p, double max_spin) {
    PetscInt n_converged = 0;
    COREMODAL_PETSC(EPSGetConverged(eps, &n_converged));
    std::vector<ZeroFrequencySpeed> out;
    for (PetscInt i = 0; i < n_converged; ++i) {
        PetscScalar c;
        COREMODAL_PETSC(EPSGetEigenvalue(eps, i, &c, nullptr));
        if (!(PetscRealPart(c) * max_spin * max_spin > 1)) continue;  // Omega^2 = 1/c >= max_spin^2, or c <= 0
        ZeroFrequencySpeed z;
        z.spin = 1 / std::sqrt(PetscRealPart(c));
        COREMODAL_PETSC(MatCreateVecs(p.K(), z.x.out(), nullptr));
        COREMODAL_PETSC(EPSGetEigenvector(eps, i, z.x, nullptr));
        z.relative_residual = residual(p, z.spin * z.spin, z.x);
        out.push_back(std::move(z));
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.spin < b.spin; });
    return out;
}

std::string mismatch_text(long counted, size_t found, double max_spin) {
    std::ostringstream s;
    s << "the inertia of K(Omega) at " << max_spin * 30 / M_PI << " rpm counts " << counted
      << " speeds of zero rotating-frame frequency below it, but the pencil's solver found " << found
      << ": raise [analysis] max_iterations";
    return s.str();
}

}  // namespace

ZeroFrequencySpeeds zero_frequency_speeds(const OperatorSet& ops, double max_spin, double rigid_omega,
                                          const SolveRequest& request) {
    ZeroFrequencySpeeds out;
    out.max_spin = max_spin;
    if (!ops.has(Term::centrifugal) || max_spin <= 0) return out;
    const Pencil pencil(ops);
    require_held(ops, pencil, rigid_omega);
    out.counted = negative_count(pencil, max_spin * max_spin, "K(Omega) at the sweep's last speed");
    if (out.counted == 0) return out;
    for (int attempt = 0; attempt < kMaxTries; ++attempt) {
        const int nev = static_cast<int>(out.counted) + kExtraEigenvalues * (1 << attempt);
        const Eps eps = configure(pencil, nev, request);
        COREMODAL_PETSC(EPSSolve(eps));
        out.speeds = below(eps, pencil, max_spin);
        if (static_cast<long>(out.speeds.size()) == out.counted) break;
    }
    if (static_cast<long>(out.speeds.size()) != out.counted)
        throw SolveError(mismatch_text(out.counted, out.speeds.size(), max_spin));
    for (const ZeroFrequencySpeed& z : out.speeds)
        if (z.relative_residual > kMaxPencilResidual)
            throw SolveError("the speed of zero rotating-frame frequency at " + std::to_string(z.spin * 30 / M_PI) +
                             " rpm has a relative residual of " + std::to_string(z.relative_residual) +
                             " (above 1e-8): raise [analysis] max_iterations");
    return out;
}

}  // namespace coremodal
