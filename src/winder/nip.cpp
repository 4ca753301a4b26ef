#include "winder/nip.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace coremodal {

Nip jorkama_nip(const NipInput& in) {
    if (!(in.roll_diameter > 0) || !(in.counter_diameter > 0) || !(in.modulus > 0))
        throw std::invalid_argument("nip: diameters and modulus must be positive");
    if (!(in.poisson >= 0 && in.poisson < 0.5)) throw std::invalid_argument("nip: Poisson ratio must be in [0, 0.5)");
    if (!(in.line_load >= 0)) throw std::invalid_argument("nip: line load must not be negative");
    if (in.line_load == 0) return {};
    const double one_minus_nu2 = 1.0 - in.poisson * in.poisson;
    const double d_star = 1.0 / (1.0 / in.roll_diameter + 1.0 / in.counter_diameter);
    const double E_star = in.modulus / one_minus_nu2;
    Nip nip;
    nip.half_width = std::sqrt(2.0 * d_star * in.line_load / (M_PI * E_star));
    const double log_term = std::log(2.0 * in.roll_diameter / nip.half_width);
    if (!(log_term > 1.0))
        throw std::invalid_argument("nip: contact half-width a = " + std::to_string(nip.half_width) +
                                    " m is not small beside the roll (ln(2d/a) = " + std::to_string(log_term) +
                                    " <= 1): the line load is too high for the formula");
    nip.deflection = in.line_load * one_minus_nu2 / (M_PI * in.modulus) * (2.0 * log_term - 1.0);
    nip.stiffness_per_length = M_PI * in.modulus / (2.0 * one_minus_nu2 * (log_term - 1.0));
    return nip;
}

}  // namespace coremodal
