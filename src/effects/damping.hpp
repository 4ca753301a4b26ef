// Damping ([damping], docs/how-to/response.md), stated once for every model level.
//
//   effect            every level (analyses/response)
//   modal_damping     zeta per elastic mode at rest: the base ratio, a family's (bending, ...)
//                     or the mode's own (the beam's lateral modes, the harmonic level's n = 1,
//                     the solid's modes below the cutoff)
//   rayleigh_damping  alpha M + beta K: the matrix in the direct solve,
//                     zeta_j = alpha/(2 omega_j) + beta omega_j/2 in the modes
//   structural_damping  a loss factor eta per part: the complex stiffness
//                     K_p (1 + i eta_p) of each part's cells (solid, harmonic)
//                     or elements (beam), H = sum_p eta_p K_p in the direct
//                     solve, Phi^T H Phi in the modes (StructuralDamping below)
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
// the first critical speed, is not modelled (the field measures one relative
// damping per roll, a decay, I-1). A loss factor per part (below) is the
// material's own loss, in the same stationary-frame equations.
//
// The single-mode check (I-2...4): a force of constant amplitude F at
// frequency f on a mode of frequency fn gives F / k times
//     d(r) = 1 / sqrt((1 - r^2)^2 + (2 zeta r)^2),   r = f / fn.
#pragma once

#include "scene/damping_input.hpp"
#include "scene/response_spec.hpp"

#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

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

// Structural (hysteretic) damping: each part's material loses the fraction
// 2 pi eta of its peak strain energy per cycle whatever the frequency (a
// complex modulus E (1 + i eta); Nashif, Jones & Henderson, Vibration
// Damping, Wiley 1985, ch. 2; eta is the loss tangent tan delta of dynamic
// mechanical analysis, measured for paper in-plane by Lif & Fellers, Nordic
// Pulp & Paper Research Journal 14(1) 82-91, 1999). In the frequency domain
// the stiffness of part p becomes K_p (1 + i eta_p), so the equations of
// motion gain the frequency-independent term i H a with
//     H = sum_p eta_p K_p                     (hysteretic_operator below)
// and a mode at rest (M-normalised, K phi = lambda phi) the modal term
// i phi^T H phi = i eta_j lambda_j with the modal loss factor
//     eta_j = sum_p eta_p phi^T K_p phi / phi^T K phi   (the parts' strain-energy shares).
// A single mode of frequency fn under a force F at f (r = f/fn) moves F/k times
//     d_h(r) = 1 / sqrt((1 - r^2)^2 + eta^2),
// which at resonance (r = 1) is 1/eta, the viscous 1/(2 zeta) with
// zeta = eta / 2, and off resonance differs from the viscous d(r) as
// eta against 2 zeta r (less damping above resonance, more below). Its free
// vibration, a root of lambda^2 + lambda_j (1 + i eta) = 0, has
// lambda = i omega_j sqrt(1 + i eta): zeta = sin(atan(eta) / 2), eta / 2 to
// first order, the eigensolvers' damped modes (eigensolve/damped_modes.hpp).
// Springs (spring layers, bearings) are effects, not parts: they carry no
// loss factor here (their losses are in the modal ratios).
struct StructuralDamping {
    static constexpr const char* kName = "structural_damping";
    double base = 0;                       // eta of every part not named
    std::map<std::string, double> parts;   // "core", "rest_paper", "chucks"
    bool given() const {
        if (base > 0) return true;
        for (const auto& [part, eta] : parts)
            if (eta > 0) return true;
        return false;
    }
    // eta of a part of a mesh or network: "core", "rest_paper", "chuck_<end>" (the "chucks" key).
    double of(std::string_view part) const {
        const std::string key = part.starts_with("chuck") ? "chucks" : std::string(part);
        const auto it = parts.find(key);
        return it != parts.end() ? it->second : base;
    }
    // eta_j of an M-normalised mode of eigenvalue lambda (rad^2/s^2), given phi^T H phi.
    static double modal_loss_factor(double phi_H_phi, double lambda) { return lambda > 0 ? phi_H_phi / lambda : 0.0; }
    // The viscous ratio with the same response at resonance.
    static double equivalent_zeta(double eta) { return eta / 2; }
};

// H = sum_p eta_p K_p over the parts (each part's stiffness from part_stiffness(name),
// only for parts with eta_p > 0): the one place the loss factors become an operator,
// for dense and sparse matrices alike.
template <class Matrix, class PartStiffness>
Matrix hysteretic_operator(const StructuralDamping& d, const std::vector<std::string>& part_names, Matrix zero,
                           PartStiffness part_stiffness) {
    for (const std::string& part : part_names)
        if (const double eta = d.of(part); eta > 0) zero += eta * part_stiffness(part);
    return zero;
}

// The damping a spinning model's operator sets carry as terms (the Campbell
// sweep's complex modes): the viscous D = alpha M + beta K (Term::damping)
// and the imaginary stiffness H = sum_p w_p K_p (Term::imaginary_stiffness)
// with w_p = eta_p, the part's loss factor. A level builds the terms from
// these; the solvers see only the terms.
struct OperatorDamping {
    RayleighDamping viscous;
    StructuralDamping structural;
    bool has_viscous() const { return viscous.alpha != 0 || viscous.beta != 0; }
    // w_p for each part (indexed as `parts`), empty when no part has one.
    std::vector<double> imaginary_stiffness_weights(const std::vector<std::string>& parts) const {
        if (!structural.given()) return {};
        std::vector<double> w;
        for (const std::string& part : parts) w.push_back(structural.of(part));
        return w;
    }
};

// [damping]'s loss factors as the effect.
inline StructuralDamping structural_damping_of(const DampingSpec& spec) {
    return {spec.loss_factor, spec.part_loss_factors};
}

// [damping] as terms of operator sets; a Campbell sweep takes only these
// (a modal ratio belongs to the modes at rest, which the spin mixes).
inline OperatorDamping operator_damping_of(const DampingSpec& spec) {
    const RayleighSpec rayleigh = spec.rayleigh.value_or(RayleighSpec{});
    return {{rayleigh.alpha, rayleigh.beta}, structural_damping_of(spec)};
}
// The keys that give them, as an error message's example.
inline constexpr const char* kOperatorDampingKeys =
    "rayleigh = { zeta = 0.01, frequencies = [\"20 Hz\", \"200 Hz\"] } (the same ratio at two frequencies) and/or "
    "loss_factor = 0.02";
// The effects they are (kName), for the effects list.
inline std::vector<std::string> operator_damping_effects(const DampingSpec& spec) {
    std::vector<std::string> out;
    if (spec.rayleigh) out.push_back(RayleighDamping::kName);
    if (structural_damping_of(spec).given()) out.push_back(StructuralDamping::kName);
    return out;
}
// Which terms they are, from which keys, a line each for the run's echo.
inline std::vector<std::string> operator_damping_words(const DampingSpec& spec) {
    std::vector<std::string> out;
    if (spec.rayleigh)
        out.push_back(spec.source + ": viscous D = alpha M + beta K (Term::damping) on each wave number's set");
    if (const std::string words = loss_factor_words(spec); !words.empty())
        out.push_back("[damping] " + words + ": structural H = sum_p eta_p K_p over the parts' section cells, the "
                      "complex stiffness K + i H (springs carry none)");
    return out;
}

// The single-mode amplification with a loss factor, d_h(r) above.
inline double hysteretic_amplification(double frequency_ratio, double eta) {
    const double r2 = frequency_ratio * frequency_ratio;
    return 1.0 / std::sqrt((1 - r2) * (1 - r2) + eta * eta);
}

}  // namespace coremodal
