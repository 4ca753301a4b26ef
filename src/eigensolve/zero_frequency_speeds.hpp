// The spin speeds at which a spinning structure has a mode of frequency
// zero (docs/theory/rotation-solid.md, "Critical speeds in co-rotating coordinates").
//
// In co-rotating coordinates (models/solid/rotating_frame.hpp) a scene
// solves M q'' + Omega G_c q' + K(Omega) q = 0 with K(Omega) = K +
// Omega^2 K_Omega, K_Omega = K_sigma1 - M_P. Where a mode's rotating-frame
// frequency is zero the gyroscopic term drops out (it multiplies omega), so
// those speeds are exactly the Omega with K(Omega) x = 0: the eigenvalues
// mu = Omega^2 of the symmetric pencil
//
//     K x = mu B x,    B = -K_Omega = M_P - K_sigma1.
//
// K is symmetric positive definite for a held structure (checked: no
// eigenvalue of K x = lambda M x below the rigid line), B symmetric and
// indefinite. Then with C = K^-1/2 B K^-1/2 (eigenvalues c = 1/mu)
//     K - s B = K^1/2 (I - s C) K^1/2,
// so by Sylvester's law neg(K - s B) = #{c > 1/s} = #{0 < mu < s} exactly,
// multiplicity counted, for every s > 0: the number of zero-frequency
// speeds below Omega_max is the inertia of K(Omega_max), the factor the
// gyroscopic solver's guard already takes. Every eigenvalue is real (a
// symmetric-definite pencil), so nothing lies off the axis to be missed.
//
// Solved as B x = c K x (K is the pencil's positive definite matrix, so
// SLEPc's GHEP applies, its inner product K's): the wanted c are the
// largest, well apart from the cluster of the stiff modes' c ~ 0, and the
// operator K^-1 B needs one Cholesky factor of K.
//
// Generalised to a rotating-frame frequency omega = r Omega (r >= 0; r = 0
// above): with q = x e^{i omega t} the equation reads
//     (K + Omega^2 K_Omega - omega^2 M + i omega Omega G_c) x = 0,
// i.e. K x = Omega^2 B_r x with the Hermitian
//     B_r = M_P - K_sigma1 + r^2 M - i r G_c     (G_c real skew: i G_c Hermitian).
// The same argument counts its eigenvalues Omega^2 below s by neg(K - s B_r).
// PETSc is built real here, so x = a + i b is solved in the real symmetric
// form of size 2n, interleaved (a_1, b_1, a_2, b_2, ...):
//     K_2 = diag(K, K),   B_2 = [[A, r G_c], [-r G_c, A]] per node pair of rows,
// A = M_P - K_sigma1 + r^2 M (B_2 x_2 is B_r x split into its real and
// imaginary parts; symmetric since G_c^T = -G_c). Each complex eigenvector x
// gives two real ones, x and i x, so every eigenvalue appears twice and the
// 2n inertia is twice the complex count (`copies`).
#pragma once

#include "assembly/operator_set.hpp"
#include "common/petsc_handle.hpp"
#include "eigensolve/modal_solver.hpp"  // SolveRequest

#include <vector>

namespace coremodal {

struct ZeroFrequencySpeed {
    double spin = 0;  // rad/s, Omega with K(Omega) x = 0 (r > 0: a mode at omega = r Omega)
    PetscVector x;    // the eigenvector's real part a (n entries), x_2^T K_2 x_2 = 1
    PetscVector y;    // r > 0: its imaginary part b (n entries); r = 0: empty
    // ||K x - mu B x|| / ((||K||_1 + mu ||B||_1) ||x||)
    double relative_residual = 0;
};

struct ZeroFrequencySpeeds {
    std::vector<ZeroFrequencySpeed> speeds;  // ascending, each eigenvalue of a multiple one once per (real) vector
    long counted = 0;                         // neg (K - max_spin^2 B): the number below max_spin, proven
    double max_spin = 0;                      // rad/s
    double ratio = 0;                         // r
    // Real vectors per complex one: 1 for r = 0 (B real), 2 for r > 0 (x
    // and i x); `counted` and `speeds` hold each complex eigenvalue this often.
    int copies = 1;
};

// Every speed 0 < Omega < max_spin (rad/s) where K(Omega) of the set is
// singular, with its null vector; verified (residual below 1e-8) and
// counted as above. A set without Term::centrifugal has none (K does not
// change with speed). SolveError when K is not positive definite (a free
// structure: rigid modes below rigid_omega, rad/s), when the count and the
// found eigenvalues differ after the retries, or a residual is too large.
ZeroFrequencySpeeds zero_frequency_speeds(const OperatorSet& operators, double max_spin, double rigid_omega,
                                          const SolveRequest& request);

// The same for B_r, ratio = r >= 0 (r = 0: zero_frequency_speeds): every
// speed 0 < Omega < max_spin where a mode's rotating-frame angular
// frequency is r Omega, verified and counted alike (in the real form's
// 2n dimensions for r > 0).
ZeroFrequencySpeeds frequency_ratio_speeds(const OperatorSet& operators, double ratio, double max_spin,
                                           double rigid_omega, const SolveRequest& request);

}  // namespace coremodal
