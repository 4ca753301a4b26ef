// The spin speeds at which a spinning structure has a mode of frequency
// zero (docs/rotation.md, "Critical speeds in co-rotating coordinates").
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
#pragma once

#include "assembly/operator_set.hpp"
#include "common/petsc_handle.hpp"
#include "eigensolve/modal_solver.hpp"  // SolveRequest

#include <vector>

namespace coremodal {

struct ZeroFrequencySpeed {
    double spin = 0;  // rad/s, Omega with K(Omega) x = 0
    PetscVector x;    // real, x^T K x = 1
    // ||K x - mu B x|| / ((||K||_1 + mu ||B||_1) ||x||)
    double relative_residual = 0;
};

struct ZeroFrequencySpeeds {
    std::vector<ZeroFrequencySpeed> speeds;  // ascending, each eigenvalue of a multiple one once per vector
    long counted = 0;                         // neg K(max_spin): the number below max_spin, proven
    double max_spin = 0;                      // rad/s
};

// Every speed 0 < Omega < max_spin (rad/s) where K(Omega) of the set is
// singular, with its null vector; verified (residual below 1e-8) and
// counted as above. A set without Term::centrifugal has none (K does not
// change with speed). SolveError when K is not positive definite (a free
// structure: rigid modes below rigid_omega, rad/s), when the count and the
// found eigenvalues differ after the retries, or a residual is too large.
ZeroFrequencySpeeds zero_frequency_speeds(const OperatorSet& operators, double max_spin, double rigid_omega,
                                          const SolveRequest& request);

}  // namespace coremodal
