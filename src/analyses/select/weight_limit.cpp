#include "analyses/select/weight_limit.hpp"

#include "beam/formulas.hpp"
#include "common/format.hpp"
#include "durability/durability_limits.hpp"
#include "durability/power_law_fit.hpp"

#include <cmath>

namespace coremodal {
namespace {

RestRollSection section(const CoreGrade& c, double dp, double ep, double rho_p) {
    return {c.inner_diameter, c.outer_diameter, dp, c.flexural_modulus, c.density, ep, rho_p};
}

}  // namespace

WeightLimit core_weight_limit(const CoreGrade& core, const Stand& stand, const SelectionScene& scene) {
    WeightLimit w;
    if (core.data) {
        const PowerLawFit fit = fit_power_law(core.data->cycles, core.data->weights);
        w.test_chuck_weight_n =
            std::pow(10.0, reduced_log_weight(fit, scene.cycles, scene.confidence, scene.failure_probability)) *
            core.data->weight_unit_newton;
        w.method = "{28} with C = " + significant(100 * scene.confidence, 4) + " %";
    } else {
        const double log_y = std::log10(core.b0_newton) + core.b1 * std::log10(scene.cycles) +
                             reduction_factor(scene.failure_probability) * core.s_log;  // {32}
        w.test_chuck_weight_n = std::pow(10.0, log_y);
        w.method = "{32} (fitted values, no confidence)";
    }
    w.chuck_scale = std::pow(stand.chuck_length / core.test_chuck_length, stand.chuck_length_exponent);
    w.winder_factor = stand.winder_factor();
    w.weight_n = w.test_chuck_weight_n * w.chuck_scale * w.winder_factor;
    return w;
}

double paper_roll_mass(const CoreGrade& core, double diameter, double width, double paper_density) {
    // The paper's own modulus does not enter a mass; 1 Pa keeps the section valid.
    return mass_per_length(section(core, diameter, 1.0, paper_density)) * width;
}

}  // namespace coremodal
