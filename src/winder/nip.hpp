// The nip of a paper roll pressed against a drum (or the rider roll) by a
// line load: Jorkama & von Hertzen's contact of a soft roll on a hard
// cylinder (Jorkama & von Hertzen eq. (5); docs/how-to/winder.md, "The nip").
//
//   a      = sqrt(2 d* P / (pi E*)),   d* = (1/d + 1/d1)^-1,  E* = E / (1 - nu^2)
//   delta  = P (1 - nu^2) / (pi E) * [2 ln(2d/a) - 1]
//   k_nip  = dP/d(delta) = pi E / (2 (1 - nu^2) (ln(2d/a) - 1))
//
// a is the contact half-width (Hertz, with the drum rigid beside the paper),
// delta the approach of the roll's centre towards the drum's, k_nip the
// tangent stiffness per unit length of contact: what a small vibration about
// the loaded state sees. It grows as the roll gets smaller (2d/a falls).
// The formula needs ln(2d/a) > 1 (a < 2d/e): a contact a good part of the
// roll wide is outside it.
#pragma once

namespace coremodal {

struct NipInput {
    double line_load = 0;          // P, N/m (>= 0)
    double roll_diameter = 0;      // d, m (the paper roll)
    double counter_diameter = 0;   // d1, m (the drum or the rider roll)
    double modulus = 0;            // E, Pa (the roll's radial modulus)
    double poisson = 0;            // nu of the roll
};

struct Nip {
    double half_width = 0;            // a, m
    double deflection = 0;            // delta, m
    double stiffness_per_length = 0;  // k_nip, N/m^2 (N/m per m of contact)
};

// The nip at line load P. P = 0 gives a = delta = k = 0 (the contact opens:
// no spring). Throws std::invalid_argument when ln(2d/a) <= 1 or an input is
// not positive (the caller names the input that caused it).
Nip jorkama_nip(const NipInput& in);

}  // namespace coremodal
