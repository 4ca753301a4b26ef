#include "analyses/select/core_selection.hpp"

#include "beam/formulas.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

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
