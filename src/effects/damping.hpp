// Damping ([damping], docs/how-to/response.md), stated once for every model level.
//
//   effect            every level (analyses/response)
//   modal_damping     zeta per elastic mode at rest: the base ratio, a family's (bending, ...)
//                     or the mode's own (the beam's lateral modes, the harmonic level's n = 1,
//                     the solid's modes below the cutoff)
//   rayleigh_damping  alpha M + beta K: the matrix in the direct solve,
//                     zeta_j = alpha/(2 omega_j) + beta omega_j/2 in the modes
//
// Modal damping gives each mode at rest (K phi = lambda M phi, M-orthonormal)
// the modal damping force 2 zeta omega_j eta_j', omega_j = sqrt(lambda_j):
// in the modal coordinates D_hat = diag(2 zeta_j omega_j). The same damping
// as a matrix on the DOFs is D = M Phi D_hat Phi^T M (with the complete basis
// Phi; Phi^T D Phi = D_hat by M-orthonormality): that is what the direct
// frequency-response solve uses to check the superposition. Rayleigh damping
// D = alpha M + beta K is diagonal in the same modes, Phi^T D Phi =
// diag(alpha + beta lambda_j), so both forms mix: a mode with a ratio of its
// own takes 2 zeta_j omega_j in place of alpha + beta lambda_j, and the
// matrix is alpha M + beta K + M Phi diag(the differences) Phi^T M. Either
// acts on the absolute velocity in the stationary frame (bearings, air, the
// web); a rotating (internal) damping, which drives whirl instability above
// the first critical speed, is not modelled, nor loss factors per part (the
// field measures one relative damping per roll, a decay, I-1).
//
// The single-mode check (I-2...4): a force of constant amplitude F at
// frequency f on a mode of frequency fn gives F / k times
//     d(r) = 1 / sqrt((1 - r^2)^2 + (2 zeta r)^2),   r = f / fn.
#pragma once

#include "scene/damping_input.hpp"

#include <cmath>

namespace coremodal {

struct ModalDamping {
    static constexpr const char* kName = "modal_damping";
    // The modal damping coefficient of a mode of angular frequency omega_n (rad/s): 2 zeta omega_n.
    static double coefficient(double zeta, double omega_n) { return 2 * zeta * omega_n; }
};

// Rayleigh damping D = alpha M + beta K (alpha in 1/s, beta in s).
struct RayleighDamping {
    static constexpr const char* kName = "rayleigh_damping";
    double alpha = 0, beta = 0;
    // Phi^T D Phi of an M-normalised mode of eigenvalue lambda = omega^2 (rad^2/s^2).
    double coefficient(double lambda) const { return alpha + beta * lambda; }
    // The modal ratio it gives a mode of angular frequency omega (rad/s):
    // alpha + beta omega^2 = 2 zeta omega.
    double zeta(double omega) const { return alpha / (2 * omega) + beta * omega / 2; }
    // The alpha and beta that give the ratio zeta at both omega_1 and omega_2
    // (rad/s, distinct): zeta(omega) = zeta there, below zeta between them
    // and above it outside (Chopra, Dynamics of Structures, chapter 11: Rayleigh damping).
    static RayleighDamping at_two_frequencies(double zeta, double omega_1, double omega_2) {
        const RayleighSpec s = rayleigh_at_two_frequencies(zeta, omega_1, omega_2);
        return {s.alpha, s.beta};
    }
};

// I-2...4: the dynamic amplification of a single mode, d(r) above.
inline double amplification(double frequency_ratio, double zeta) {
    const double r2 = frequency_ratio * frequency_ratio;
    return 1.0 / std::sqrt((1 - r2) * (1 - r2) + 4 * zeta * zeta * r2);
}

}  // namespace coremodal
