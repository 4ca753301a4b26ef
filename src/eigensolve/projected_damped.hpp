// The complex modes of an operator set with damping, at many speeds for the
// price of one basis: the projected quadratic solver's damped branch
// (projected_gyroscopic.hpp is the undamped one, whose Hermitian
// linearisation and inertia count a damping term breaks).
//
// Once per set: a basis V (N x m, M-orthonormal) of the lowest `n_rest`
// modes at rest of (K + K_sigma, M) and the static responses
// S^-1 A phi (and S^-1 M S^-1 A phi) of each mode to every force the modes
// at rest do not diagonalise, A = G, D, H, K_Omega, S = K + K_sigma + tau^2 M
// (projection_basis.hpp); every term projected once, V^T A V.
// Per speed: the small damped problem solved whole (damped_modes.hpp: the
// viscous D = Term::damping, the gyroscopic Omega G, the imaginary stiffness
// H = Term::imaginary_stiffness of the complex stiffness K + i H), each mode lambda = -zeta omega + i omega
// sqrt(1 - zeta^2) with its shape x = V y.
//
// Nothing of the small problem is trusted: each mode's relative residual is
// computed on the full set,
//     ||Q(lambda) x|| / ((||K(Omega)|| + ||H|| + |lambda| (||D|| + Omega ||G||) + |lambda|^2 ||M||) ||x||),
// (1-norms of the full matrices, once per set). For a lightly damped,
// nearly normal problem (eigenvalue condition ~1) it bounds the eigenvalue's
// relative error to first order; measured far below it, of the order of its square: 1e-12 at a residual of
// 3e-8, 1.4e-10 at 1.6e-6, tests/unit/eigensolve/test_projected_damped.cpp). Completeness is not proven by a count (a
// damped pencil has no inertia); a mode with Rayleigh damping is a mode at rest with the same shape, so the rest basis
// carries it exactly, and the residual says how well a basis carries the
// others. Which residual to accept is the caller's: the undamped branch's
// kMaxProjectedResidual bounds the shape, and is stricter than the
// frequency needs.
// One process (as the undamped branch).
#pragma once

#include "assembly/operator_set.hpp"
#include "eigensolve/damped_modes.hpp"
#include "eigensolve/modal_solver.hpp"

#include <Eigen/Dense>

namespace coremodal {

class ProjectedDamped {
public:
    // `operators`: K and M, and any of Term::geometric_stiffness,
    // Term::centrifugal, Term::gyroscopic, Term::damping (viscous D),
    // Term::imaginary_stiffness (H). `request`: lambda_scale (the rigid
    // line and the target tau, as the undamped branch's), tolerance.
    ProjectedDamped(const OperatorSet& operators, const SolveRequest& request, int n_rest);

    // The oscillating modes at spin `spin` (rad/s), ascending damped
    // frequency; backward_error is the full set's relative residual above.
    DampedModes modes_at(double spin) const;
    // A mode's shape on the full set's DOFs, x = V y.
    Eigen::VectorXcd full_shape(const DampedMode& mode) const { return V_.cast<std::complex<double>>() * mode.shape; }
    int basis_size() const { return static_cast<int>(V_.cols()); }

private:
    // The full set's terms times V (N x m), for the residuals; empty when absent.
    struct Applied {
        Eigen::MatrixXd K, K_omega, M, G, D, H;
    };
    double full_residual(const DampedMode& mode, double spin) const;

    Eigen::MatrixXd V_;
    Applied applied_;
    ProjectedDampedModel projected_;  // K: V^T (K + K_sigma) V
    Eigen::MatrixXd K_omega_;         // V^T K_Omega V (empty: none)
    double norm_K_ = 0, norm_K_omega_ = 0, norm_M_ = 0, norm_G_ = 0, norm_D_ = 0, norm_H_ = 0;  // 1-norms
    double rigid_omega_ = 0;
};

}  // namespace coremodal
