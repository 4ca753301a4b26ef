#include "eigensolve/projected_gyroscopic.hpp"

#include "eigensolve/projected_problem.hpp"

#include "eigensolve/band_edge.hpp"
#include "common/error.hpp"
#include "eigensolve/gyroscopic_inertia.hpp"
#include "eigensolve/projection_basis.hpp"
#include "eigensolve/tolerances.hpp"

#include <Eigen/Dense>

#include "common/blas_threads.hpp"
#include "common/log_event.hpp"
#include <algorithm>
#include <cmath>
#include <complex>

namespace coremodal {

ProjectedGyroscopic::~ProjectedGyroscopic() = default;

ProjectedGyroscopic::ProjectedGyroscopic(const OperatorSet& ops, const SolveRequest& request, int n_rest, IS first,
                                         IS second)
    : basis_(std::make_unique<Basis>()) {
    const LogEvent event("CmProjBasis");
    Basis& b = *basis_;
    COREMODAL_ASSERT(ops.has(Term::gyroscopic) && !ops.has(Term::damping) && !ops.has(Term::imaginary_stiffness) &&
                     !request.lambda_max);
    COREMODAL_ASSERT(mpi_size(PetscObjectComm((PetscObject)ops.K())) == 1);
    b.request = request;
    b.rigid_omega = gyroscopic_rigid_omega(request);
    b.centrifugal = ops.has(Term::centrifugal);
    const EffectiveStiffness at_rest(ops, 0.0);  // K + K_sigma
    b.K_template = ops.K();
    {
        const LogEvent setup("CmInertiaSetup");
        b.inertia = std::make_unique<GyroscopicInertia>(ops, first, second);
    }
    // The matrices the basis is built from, projected on and verified with:
    // the whole set's, or one family's when the families are mirrored
    // (family_candidates says why that is exact).
    const GyroscopicInertia::FamilyBlocks family = b.inertia->family_blocks();
    b.family = family.stiffness != nullptr;
    const Mat K0 = b.family ? family.stiffness : at_rest.get(), M = b.family ? family.mass : ops.M(),
              G = b.family ? family.coupling : ops[Term::gyroscopic];
    const Mat K_omega = b.centrifugal ? (b.family ? family.centrifugal : ops[Term::centrifugal]) : nullptr;
    // Every mode of one family at rest is a pair of the set's.
    int n_basis_rest = std::max(n_rest, request.n_modes);
    if (b.family) {
        n_basis_rest = (n_basis_rest + 1) / 2 + 1;
        b.first_rows = indices_of(first);
        b.second_rows = indices_of(second);
    }

    // 1. The modes at rest and the static responses to their spin forces.
    const SolvedModes rest = [&] {
        const LogEvent event("CmProjRestModes");
        return rest_modes(K0, M, ops.model_mass, request, n_basis_rest);
    }();
    std::vector<Mat> forces{G};
    if (b.centrifugal) forces.push_back(K_omega);
    const double tau = kTargetFraction * std::sqrt(request.lambda_scale);
    const std::vector<Eigen::VectorXd> enrichment = [&] {
        const LogEvent event("CmProjStatic");
        return static_responses(K0, M, tau, forces, rest.vectors);
    }();

    // 2. The basis, M-orthonormal (twice: the second pass removes what round-off left of the first's error).
    PetscInt n_dofs;
    COREMODAL_PETSC(MatGetSize(K0, &n_dofs, nullptr));
    Dense V(n_dofs, rest.vectors.size() + enrichment.size());
    Eigen::Index col = 0;
    for (const PetscVector& x : rest.vectors) V.col(col++) = values_of(x);
    for (const Eigen::VectorXd& x : enrichment) V.col(col++) = x;
    {
        const LogEvent event("CmProjOrthonormal");
        b.V = m_orthonormal_pass(M, m_orthonormal_pass(M, V));
    }

    b.project(K0, K_omega, M, G, n_dofs);  // 3
    b.residual_norms(K0, K_omega, M, G);   // 4
}

std::optional<GyroscopicModes> ProjectedGyroscopic::modes_at(double spin) const {
    const Basis& b = *basis_;
    const double scale = b.request.lambda_scale;
    // Small fronts and small dense problems: OpenBLAS's second thread only
    // waits (sched_yield in the profile of a sweep), common/blas_threads.hpp.
    const SingleThreadBlas one_thread;
    std::vector<ProjectedCandidate> c = [&] {
        const LogEvent event("CmProjSmall");
        return b.candidates(spin);
    }();
    std::stable_sort(c.begin(), c.end(),
                     [](const ProjectedCandidate& x, const ProjectedCandidate& y) { return x.omega < y.omega; });
    const std::vector<double> lambdas = squared_omegas(c);
    const int n_report = reported_count(lambdas, b.request.n_modes, scale);
    if (n_report < b.request.n_modes) return std::nullopt;

    GyroscopicModes out;
    Verification& v = out.verification;
    std::vector<double> residuals;
    const double norm_K = b.norm_K(spin);  // once per speed: a pass over the full matrices
    {
        const LogEvent event("CmProjResidual");
        for (int i = 0; i < n_report; ++i) {
            residuals.push_back(b.relative_residual(spin, c[i].omega, c[i], norm_K));
            if (residuals.back() > (c[i].omega > 0 ? kMaxProjectedResidual : kMaxRigidModeResidual)) return std::nullopt;
            v.max_relative_residual = std::max(v.max_relative_residual, residuals.back());
        }
    }
    const double band_edge = std::sqrt(check_point(lambdas, n_report, scale));
    const long below_rigid_line =
        spin <= b.rigid_line_clear_up_to ? 0 : b.inertia->negative_count(spin, b.rigid_omega);
    // The count's premise (gyroscopic_solver.hpp): K(Omega) + omega_0^2 M >= 0,
    // proven by interlacing where nothing is below the rigid line, for the
    // sweep by prove_rigid_line_clear, or here by one more count.
    if (below_rigid_line > 0 && spin > b.stiffness_clear_up_to) {
        const long soft = b.inertia->negative_count(stiffness_at(spin, b.rigid_omega));
        if (soft > 0) throw SolveError(indefinite_stiffness_text(spin, soft));
    }
    const Basis::Count count = b.count_modes(spin, c, n_report, band_edge, norm_K);
    const double check = count.point;
    const long counted = count.negative - below_rigid_line, found = count.found;
    if (counted != found) return std::nullopt;

    for (int i = 0; i < n_report; ++i) out.modes.push_back(b.full_mode(c[i], residuals[i]));
    v.max_orthonormality_error = b.orthogonality_error(spin, c, n_report);
    v.check_shift = check * check;
    v.negative_pivots_at_shift = counted;
    v.modes_below_shift = counted;
    v.complete = true;
    return out;
}

bool ProjectedGyroscopic::prove_rigid_line_clear(double max_spin) {
    Basis& b = *basis_;
    const SingleThreadBlas one_thread;
    const double w0 = b.rigid_omega;
    bool clear = b.inertia->negative_count(0.0, 0.0, w0) == 0 && b.inertia->negative_count(max_spin, 0.0, w0) == 0;
    if (clear && b.centrifugal) clear = b.inertia->negative_count(max_spin, max_spin * max_spin, w0) == 0;
    if (clear) {
        // neg Q(omega_0) = 0 at every speed of the range implies the count's
        // premise there (interlacing, gyroscopic_solver.hpp).
        b.rigid_line_clear_up_to = b.stiffness_clear_up_to = max_spin;
        try {
            b.prove_bounds();
        } catch (const SolveError&) {  // a count's factorisation failed: count at every speed
        }
        return true;
    }
    // The premise on its own: K(Omega) + omega_0^2 M is affine in Omega^2, so
    // positive semi-definite at Omega = 0 and at the top speed (the
    // semi-definite matrices are a convex set) means at every speed between.
    bool stiff = b.inertia->negative_count(stiffness_at(0.0, w0)) == 0;
    if (stiff && b.centrifugal) stiff = b.inertia->negative_count(stiffness_at(max_spin, w0)) == 0;
    if (stiff) b.stiffness_clear_up_to = max_spin;
    return false;
}

ProjectedGyroscopic::CountStatistics ProjectedGyroscopic::count_statistics() const { return basis_->stats; }

int ProjectedGyroscopic::basis_size() const { return static_cast<int>(basis_->m()); }

bool ProjectedGyroscopic::counts_mirrored_families() const { return basis_->inertia->uses_mirrored_families(); }

}  // namespace coremodal
