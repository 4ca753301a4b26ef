#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

namespace {

double disc_area(double d_out, double d_in) { return M_PI / 4 * (d_out * d_out - d_in * d_in); }

}  // namespace

double Scene::roll_mass() const {
    double m = core.material.density * disc_area(core.outer_diameter, core.inner_diameter) * core.length;
    if (rest_paper)
        m += rest_paper->material.density * disc_area(rest_paper->outer_diameter, core.outer_diameter) * core.length;
    return m;
}

double Scene::mass_from_dimensions() const {
    double m = roll_mass();
    for (const ChuckSpec& c : supports.chucks) {
        m += c.material.density *
             (disc_area(c.body_diameter, 0) * c.inserted_length + disc_area(c.shaft_diameter, 0) * c.shaft_length);
        m += c.bearing.frame_mass.value_or(0.0);
    }
    return m;
}

double ChuckSpec::li() const {
    double li = 0;
    for (const ExpandingElement& e : expanding) li = std::max(li, e.center);
    return li;
}

}  // namespace coremodal
