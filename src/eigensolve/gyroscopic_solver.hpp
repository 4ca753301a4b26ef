// The modes of a spinning structure (effects/rotation.hpp): an operator set
// with a gyroscopic term G (per unit spin speed) spinning at Omega,
//
//     M q'' + Omega G q' + K q = 0,   q = x e^{i omega t}:
//     Q(omega) x = (K - omega^2 M + i omega Omega G) x = 0,
//
// K the stiffness plus any geometric stiffness and Omega^2 K_Omega (the
// centrifugal term, element/term.hpp): symmetric, positive semi-definite
// for a structure that spins below its divergence speed (the count below
// assumes it), M symmetric positive definite, G
// skew-symmetric. A quadratic eigenproblem in omega, solved with SLEPc's PEP
// (TOAR) on P(lambda) = K + lambda Omega G + lambda^2 M, lambda = i omega.
//
// Shift-and-invert at a real target tau > 0: |i omega - tau|^2 = omega^2 +
// tau^2, so the eigenvalues nearest tau are exactly those of lowest |omega|,
// the lowest modes, and P(tau) is never singular (x^T P(tau) x = x^T (K +
// tau^2 M) x > 0 for real x): rigid-body modes need no negative shift.
//
// Completeness, by inertia as for K x = lambda M x. For real omega, Q(omega)
// is Hermitian (i G is Hermitian); at a mode omega > 0 with Q x = 0 the
// eigenvalue of Q through zero moves with
//     d mu / d omega = x^H Q'(omega) x / x^H x = -(omega^2 x^H M x + x^H K x) / (omega x^H x) < 0
// (Q' = -2 omega M + i Omega G, and x^H Q x = 0 eliminates x^H i G x), so every
// eigenvalue of Q crosses zero downwards, once for each mode. Hence the modes
// with omega_0 <= omega < omega_c number neg Q(omega_c) - neg Q(omega_0):
// Sylvester's count on a Hermitian matrix, taken on its real symmetric form
// [[A, -B], [B, A]] (A = K - omega^2 M, B = omega Omega G), whose eigenvalues
// are Q's, each twice. omega_0 is the rigid line: modes below it are rigid
// (or the slow precession of a free spinning body) and are reported, not
// counted (tolerances.hpp says why the line sits higher than the symmetric
// solver's). At Omega = 0 this is the symmetric solver's count.
//
// The count needs less than K >= 0: a mode omega > omega_0 crosses
// downwards when x^H K x > -omega^2 x^H M x, so K(Omega) + omega_0^2 M >= 0
// (no eigenvalue of K(Omega) x = lambda M x below -omega_0^2) is enough. It
// holds wherever neg Q(omega_0) = 0, the usual case, for free: Q(omega_0)'s
// real form restricted to real vectors (x, 0) is K(Omega) - omega_0^2 M, and
// a restriction has no more negative eigenvalues than the whole (Cauchy's
// interlacing). Where Q(omega_0) has negative eigenvalues (rigid modes, or a
// stiffness that the spin has made indefinite) one more count, of
// K(Omega) + omega_0^2 M, decides; when it is not zero the count proves
// nothing: no modes are reported at that speed, and SolveError says why
// (indefinite_stiffness_text). It happens where the centrifugal softening
// outgrows the stiffness: in co-rotating coordinates (models/solid/
// rotating_frame.hpp) above the first forward critical speed of order 1,
// where a forward whirl's rotating-frame frequency has passed through zero.
//
// Orthogonality: for modes of different frequency the equations of the two
// give x_j^H ((omega_i + omega_j) M - i Omega G) x_i = 0 (not x_j^H M x_i = 0),
// and x^H (2 omega M - i Omega G) x = (omega^2 x^H M x + x^H K x) / omega > 0
// is each mode's norm in that product; the verification reports the largest
// normalised product of two modes of distinct frequency.
//
// A damping term (no Hermitian Q, no count) is refused for now.
#pragma once

#include "assembly/operator_set.hpp"
#include "common/petsc_handle.hpp"
#include "eigensolve/modal_solver.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The target tau = this fraction of the first elastic frequency's scale
// (sqrt(lambda_scale)): any tau > 0 finds the lowest modes first (above);
// one of the order of the wanted frequencies keeps them well apart in the
// transformed spectrum 1 / (lambda - tau). The projected solvers shift their
// static responses by the same tau: S = K (+ K_sigma) + tau^2 M is positive
// definite with rigid modes or not.
inline constexpr double kTargetFraction = 0.5;

struct GyroscopicMode {
    double omega = 0;          // rad/s, >= 0
    PetscVector real, imag;    // x = real + i imag, x^H M x = 1
    // ||Q(omega) x|| / ((||K|| + omega Omega ||G|| + omega^2 ||M||) ||x||), 1-norms of the matrices
    double relative_residual = 0;
};

struct GyroscopicModes {
    std::vector<GyroscopicMode> modes;  // ascending omega: rigid ones first
    // max_relative_residual; max_orthonormality_error = the largest
    // normalised x_j^H ((omega_i + omega_j) M - i Omega G) x_i of modes of
    // distinct frequency; check_shift = omega_c^2 (rad^2/s^2);
    // negative_pivots_at_shift = neg Q(omega_c) - neg Q(omega_0), modes_below_shift
    // = the modes found in [omega_0, omega_c).
    Verification verification;
};

// The lowest request.n_modes modes (degenerate partners of the last one
// included; a band request is refused) at spin speed `spin` (rad/s) of an
// operator set with a gyroscopic term (or none: then the modes at rest).
// Verified and proven complete as above; SolveError otherwise.
GyroscopicModes solve_gyroscopic(const OperatorSet& operators, double spin, const SolveRequest& request,
                                 const Progress& progress);

// The rigid line omega_0 (rad/s) of a request: kQuadraticRigidFrequencyFraction
// of sqrt(lambda_scale) (tolerances.hpp). Modes below it are rigid.
double gyroscopic_rigid_omega(const SolveRequest& request);

// neg Q(omega) / 2: the modes with frequency below omega (rad/s), rigid
// modes included as their null directions dictate (see above).
long count_gyroscopic_below(const OperatorSet& operators, double spin, double omega);

// Why no modes are reported at spin speed `spin` (rad/s): the effective
// stiffness K(Omega) has `n_negative` eigenvalues (against M) below
// -omega_0^2 there (above); what it means and what the user can do.
std::string indefinite_stiffness_text(double spin, long n_negative);

}  // namespace coremodal
