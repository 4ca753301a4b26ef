// A closed-form estimate of the lowest drum bending frequency with the rolls
// on the drums, for isotropic drum bearings (docs/how-to/winder.md, "The
// drum-frequency estimate").
//
// NOT the paper's eq. 9: Jorkama & von Hertzen's text was not available to
// us; this is our derivation of the limit such an approximation represents.
// With isotropic bearings each drum's motion splits into the component along
// its nip line (coupled to the rolls) and the one across it (untouched: a
// mode at the drum-alone frequency at every roll diameter). The coupled
// motions pair up by symmetry: both drums moving towards the rolls
// (symmetric; the rolls move vertically) or one towards and one away
// (antisymmetric; the rolls move horizontally). Rayleigh-Ritz with two
// functions per pair: the drum's first mode phi(z) on its bearings
// (M-normalised, eigenvalue lambda_d) and the rolls moving as slices in the
// same shape over their widths. Then, per drum,
//
//   K_n     = k_nip * integral over the rolls of phi^2        (nip modal stiffness)
//   Omega^2 = 2 k_nip p^2 / m_roll,  p = cos(alpha) symmetric, sin(alpha) antisymmetric
//             (a roll of mass m_roll per width on two nips, seen along one nip line)
//   lambda^2 - (lambda_d + K_n + Omega^2) lambda + lambda_d Omega^2 = 0
//
// whose root with most of its kinetic energy in the drum is the estimate. It
// rises with the nip stiffness and with the rolls' mass, towards the
// heavy-roll limit lambda_d + K_n (the rolls stand still; the drum rides on
// the nips as on an elastic foundation). It is exact to first order in the
// nips (the rolls' reaction on the drum), which is the limit the tests check;
// a soft rider (no rider load) is assumed: a rider stiffens the rolls'
// vertical motion, which the estimate leaves out.
#pragma once

#include "winder/winder_model.hpp"
#include "winder/winder_modes.hpp"

#include <array>

namespace coremodal {

enum class DrumFamily { symmetric, antisymmetric };
constexpr int kDrumFamilies = 2;

// The two roots (rad^2/s^2) of the 2x2 problem above, the drum-dominated first.
struct TwoModeRoots {
    double drum = 0, roll = 0;
};
TwoModeRoots two_mode_roots(double lambda_drum, double nip_modal_stiffness, double roll_bounce);

struct DrumFrequencyEstimate {
    bool isotropic = true;          // equal bearing stiffness in both directions
    double drum_alone_hz = 0;       // the drum on its bearings without rolls: first (vertical) mode
    double nip_modal_stiffness = 0;  // K_n, rad^2/s^2 (phi M-normalised)
    struct Family {
        double roll_bounce_hz = 0;     // Omega / 2 pi
        double drum_hz = 0;            // the estimate
        double roll_hz = 0;            // the other root
        double heavy_roll_hz = 0;      // sqrt(lambda_d + K_n) / 2 pi
        double model_hz = 0;           // the model's mode with most of this family's drum motion
        double model_participation = 0;  // its share of that motion (0..1)
    };
    std::array<Family, kDrumFamilies> family;
};

// The estimate at the model's roll diameter, and the model's matching modes
// among `modes` (the reported ones).
DrumFrequencyEstimate estimate_drum_frequency(const WinderModel& model, const WinderModes& modes);

}  // namespace coremodal
