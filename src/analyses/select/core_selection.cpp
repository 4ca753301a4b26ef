#include "analyses/select/core_selection.hpp"

#include "beam/formulas.hpp"
#include "common/format.hpp"
#include "durability/durability_limits.hpp"
#include "durability/power_law_fit.hpp"

#include <algorithm>
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

SelectionResult select_cores(const SelectionScene& scene) {
    SelectionResult r;
    r.assumptions = rest_roll_assumptions();
    for (const Stand& stand : scene.stands) {
        std::vector<CoreInStand> row;
        for (const CoreGrade& core : scene.cores) {
            CoreInStand c;
            c.fits = stand.takes(core.name);
            if (!c.fits) {
                row.push_back(c);
                continue;
            }
            c.weight = core_weight_limit(core, stand, scene);
            c.max_mass_kg = c.weight.weight_n / kStandardGravityForWeight;
            c.speed_width_m = max_width_for_speed(core, stand, scene, stand.web_speed, &c.speed_verdict);
            c.i7_width_m = i7_max_width(core, stand, scene, stand.web_speed);
            c.weight_width_m = c.max_mass_kg / paper_roll_mass(core, stand.roll_diameter, 1.0, scene.paper_density);
            c.max_width_m = std::min(c.speed_width_m, c.weight_width_m);
            c.governing = c.speed_width_m <= c.weight_width_m ? "speed" : "weight";
            c.core_mass_per_m = core.density * tube_area(core.outer_diameter, core.inner_diameter);
            row.push_back(c);
        }
        r.table.push_back(row);
    }
    for (const Reel& reel : scene.reels) {
        ReelCheck check;
        check.stand = std::find_if(scene.stands.begin(), scene.stands.end(),
                                   [&](const Stand& s) { return s.name == reel.stand; }) -
                      scene.stands.begin();
        const Stand& stand = scene.stands[check.stand];
        check.web_speed = reel.web_speed.value_or(stand.web_speed);
        for (std::size_t i = 0; i < scene.cores.size(); ++i) {
            const CoreGrade& core = scene.cores[i];
            ReelVerdict v;
            v.fits = r.table[check.stand][i].fits;
            if (!v.fits) {
                check.cores.push_back(v);
                continue;
            }
            v.mass_kg = paper_roll_mass(core, reel.diameter, reel.width, scene.paper_density);
            v.weight_ok = v.mass_kg <= r.table[check.stand][i].max_mass_kg;
            const RestRollVerdict speed = rest_roll_verdict(core, stand, scene, reel.width, check.web_speed);
            v.speed_ok = speed.passes;
            v.safe_speed_m_s = speed.safe_speed_m_s;
            v.speed_governing = speed.governing;
            check.cores.push_back(v);
            if (!v.passes()) continue;
            const double mass = r.table[check.stand][i].core_mass_per_m;
            if (!check.lightest || mass < r.table[check.stand][*check.lightest].core_mass_per_m) check.lightest = i;
            if (core.price_per_m && (!check.cheapest || *core.price_per_m < *scene.cores[*check.cheapest].price_per_m))
                check.cheapest = i;
        }
        r.reels.push_back(check);
    }
    return r;
}

}  // namespace coremodal
