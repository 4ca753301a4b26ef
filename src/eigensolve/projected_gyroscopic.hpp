// The lowest modes of a spinning operator set (gyroscopic_solver.hpp) at
// many speeds for the price of one: a Campbell sweep solves the same set at
// forty speeds and more.
//
// Once per set: a basis V (N x m, M-orthonormal) of
//   - the modes at rest, (K + K_sigma) phi = lambda M phi, the lowest
//     `n_rest` (symmetric solver, inertia-counted),
//   - what the spin adds to them: u1 = S^-1 G phi and u2 = S^-1 M u1 and,
//     with a centrifugal term, the same of K_Omega phi, S = K + K_sigma +
//     tau^2 M (positive definite, tau the gyroscopic solver's target): the
//     static response of the structure to the gyroscopic and centrifugal
//     forces of each mode at rest and the next term of its series in
//     omega^2 + tau^2, which a mode at speed needs beyond the modes at rest;
// and every term projected once: V^T (K + K_sigma) V, V^T K_Omega V, V^T G V.
// Per speed: K(Omega) = K + K_sigma + Omega^2 K_Omega combined in the basis,
// and the small problem solved whole as the beam level does (an exact
// Hermitian linearization of size 2m, Eigen, docs/theory/rotation-harmonic.md).
//
// Nothing of the small problem is trusted. Each mode x = V y is verified on
// the full set, with the relative residual of solve_gyroscopic,
//     ||Q(omega) x|| / ((||K(Omega)|| + omega Omega ||G|| + omega^2 ||M||) ||x||),
// computed without an N-sized product per mode: Q(omega) x = W c with
// W = [V, (K + K_sigma) V, K_Omega V, M V, G V] fixed and c = (0, y,
// Omega^2 y, -omega^2 y, i omega Omega y), so ||Q x|| = ||R c|| for W = Q_W R
// (Householder QR, once per set): backward stable, each column of W
// perturbed by round-off relative to its own norm, as the direct product is.
// And the set is proven complete as solve_gyroscopic proves it: the inertia
// of the full Hermitian Q(omega) at the band edge and at the rigid line
// (gyroscopic_inertia.hpp), at every speed (the rigid line's once for a
// whole sweep where prove_rigid_line_clear holds; the band edge's carried
// from an earlier speed where a certificate reaches, count_statistics).
// With mirrored families (n >= 1) the basis is one family's and the small
// problem real symmetric (projected_gyroscopic.cpp, family_candidates). A mode above kMaxProjectedResidual
// or a count that disagrees is not an answer: modes_at returns none, and the
// caller solves the full problem at that speed (solve_gyroscopic).
#pragma once

#include "assembly/operator_set.hpp"
#include "eigensolve/gyroscopic_solver.hpp"
#include "eigensolve/modal_solver.hpp"

#include <memory>
#include <optional>

namespace coremodal {

// The largest relative residual of the full problem a mode of the projected
// problem may have. The Rayleigh-Ritz step has a round-off floor: the
// projected stiffness V^T K V carries an error of eps ||K|| ||V||^2, which
// leaves the modes residuals of 4e-10 (a steel tube's first bending mode)
// to 7e-9 (a ring mode of n = 3 at 12 kHz), whatever the basis; the full
// solver accepts 1e-6 (gyroscopic_solver.cpp). A Hermitian problem's
// frequencies are accurate to about the square of the residual: the test
// against the full solver finds them equal to 1e-8 and better.
constexpr double kMaxProjectedResidual = 1e-8;
// A mode reported at 0 Hz (below the rigid line) is held to the full
// solver's bound instead (gyroscopic_solver.cpp, kMaxAcceptedResidual): its
// frequency is 0 whatever the residual, which measures its shape only, and
// the modes at rest give rigid shapes to ~1e-9 (the symmetric solver's
// residual of lambda ~ 0 against ||K||), as the full solver does.
constexpr double kMaxRigidModeResidual = 1e-6;

class ProjectedGyroscopic {
public:
    // `request`: n_modes (wanted at every speed; pairs are not cut),
    // lambda_scale (the target and the rigid line, as solve_gyroscopic's).
    // `n_rest`: the modes at rest in the basis (>= request.n_modes).
    // `first_family`, `second_family`: as GyroscopicInertia's.
    ProjectedGyroscopic(const OperatorSet& operators, const SolveRequest& request, int n_rest,
                        IS first_family = nullptr, IS second_family = nullptr);
    ~ProjectedGyroscopic();
    ProjectedGyroscopic(const ProjectedGyroscopic&) = delete;
    ProjectedGyroscopic& operator=(const ProjectedGyroscopic&) = delete;

    // The lowest request.n_modes modes at spin speed `spin` (rad/s), verified
    // and proven complete on the full set as solve_gyroscopic's; none when
    // the basis does not carry them to the residual bound or the count
    // disagrees (then solve the full problem).
    std::optional<GyroscopicModes> modes_at(double spin) const;

    // Proves, if it holds, that no mode lies below the rigid line omega_0 at
    // any spin speed in [0, max_spin] (rad/s), so that modes_at needs one
    // count per speed, not two. Q(omega_0) is affine in (Omega, Omega^2):
    // Q = A + Omega B + Omega^2 C, and the positive definite matrices are a
    // convex set; the curve (Omega, Omega^2), 0 <= Omega <= S, lies in the
    // triangle (0, 0), (S, 0), (S, S^2), so Q(omega_0) positive definite at
    // those three corners (neg = 0, three counts; two without a centrifugal
    // term, where Q is affine in Omega alone) is positive definite at every
    // speed of the range, and neg Q(omega_0) = 0 there. A wave number with
    // rigid modes (neg Q(omega_0) > 0 at rest) keeps counting at every speed.
    // Returns whether it holds.
    bool prove_rigid_line_clear(double max_spin);

    int basis_size() const;
    bool counts_mirrored_families() const;

    // Counting at fewer speeds (docs/theory/rotation-harmonic.md, "Counting at fewer
    // speeds"). After prove_rigid_line_clear has held, the sweep's counts
    // may come from a certificate: at (Omega_1, omega_1) the two counts
    // neg(Q - delta M) = neg(Q + delta M) = N say that no eigenvalue of the
    // pencil (Q, M) lies in [-delta, delta); Weyl's inequality moves each by
    // at most ||M^-1/2 (Q(Omega, omega_1) - Q(Omega_1, omega_1)) M^-1/2|| <=
    // |Omega^2 - Omega_1^2| kappa + omega_1 |Omega - Omega_1| gamma, with
    // gamma M -+ i G >= 0 and kappa M -+ K_Omega >= 0 proven by inertia
    // counts once per set; so neg Q(Omega, omega_1) = N wherever that bound
    // is below delta. A speed uses it when omega_1 lies above its reported
    // modes and every candidate below omega_1 is verified; otherwise it
    // counts, as before. Only for a set without a centrifugal term (kappa =
    // 0): with one, kappa is out of reach (projected_gyroscopic.cpp).
    struct CountStatistics {
        long speeds = 0;            // modes_at calls that reached the count
        long counted = 0;           // of them, counted at their own point (one count)
        long certificates = 0;      // of them, a new certificate made (two counts)
        long certificate_failed = 0;  // of those, the two counts differed: counted again (three)
        long certified = 0;         // of them, by an earlier certificate (no count)
        double gamma = -1;          // the proven bound (-1: none, no certificates)
    };
    CountStatistics count_statistics() const;

private:
    struct Basis;
    std::unique_ptr<Basis> basis_;
};

}  // namespace coremodal
