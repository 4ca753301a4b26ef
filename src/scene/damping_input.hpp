// What the case file's forms of [damping] mean as damping (docs/how-to/response.md):
// a measured free decay or logarithmic decrement as a modal ratio (I-1), and
// one ratio at two frequencies as Rayleigh's alpha and beta. The case reader
// turns the file's form into a DampingSpec with these; effects/damping.hpp,
// which states the damping itself and sits above scene/, uses the same ones,
// so the reader needs nothing from effects/ (issue 34: no include circle).
#pragma once

#include "scene/response_spec.hpp"  // RayleighSpec

#include <cmath>

namespace coremodal {

// I-1: zeta = ln(X0 / XN) / (2 pi N) from a free decay over N cycles; the
// logarithmic decrement delta = ln(X0 / X1) gives zeta = delta / (2 pi).
// (The light-damping form the field uses; exact would be
// delta / sqrt(4 pi^2 + delta^2), 0.05 % lower at zeta = 0.02.)
inline double zeta_from_decay(double amplitude_ratio, double cycles) {
    return std::log(amplitude_ratio) / (2 * M_PI * cycles);
}
inline double zeta_from_log_decrement(double delta) { return zeta_from_decay(std::exp(delta), 1.0); }

// The alpha (1/s) and beta (s) that give the modal ratio zeta at both omega_1
// and omega_2 (rad/s, distinct): below zeta between them and above it outside
// (Chopra, Dynamics of Structures, chapter 11: Rayleigh damping).
inline RayleighSpec rayleigh_at_two_frequencies(double zeta, double omega_1, double omega_2) {
    return {2 * zeta * omega_1 * omega_2 / (omega_1 + omega_2), 2 * zeta / (omega_1 + omega_2)};
}

}  // namespace coremodal
