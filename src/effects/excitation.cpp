#include "effects/excitation.hpp"

#include <cmath>

namespace coremodal {

double ovality_stiffness_split(double ovality_m, double outer_diameter, double inner_diameter) {
    const double delta = 0.25 * ovality_m;  // D_max - D_min = 4 delta
    const double ro = 0.5 * outer_diameter, ri = 0.5 * inner_diameter;
    return 2 * delta * (ro * ro * ro - ri * ri * ri) / (ro * ro * ro * ro - ri * ri * ri * ri);
}

double half_sine_bow(double bow_m, double z, double length) { return bow_m * std::sin(M_PI * z / length); }

double half_sine_bow_slope(double bow_m, double z, double length) {
    return bow_m * M_PI / length * std::cos(M_PI * z / length);
}

std::vector<std::string> excitation_effect_names(const ExcitationSpec& e) {
    std::vector<std::string> out;
    if (e.unbalance_kg_m > 0) out.push_back(Unbalance::kName);
    if (e.eccentricity_m > 0) out.push_back(Eccentricity::kName);
    if (e.bow_m > 0) out.push_back(Bow::kName);
    if (e.ovality_m > 0 && e.gravity) out.push_back(OvalityGravity::kName);
    if (e.gravity) out.push_back(Gravity::kName);
    return out;
}

}  // namespace coremodal
