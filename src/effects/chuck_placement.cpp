#include "effects/chuck_placement.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

ZRange ChuckPlacement::element_range(const ExpandingElement& e) const {
    const double a = z_at(e.center - e.width / 2), b = z_at(e.center + e.width / 2);
    return {std::min(a, b), std::max(a, b)};
}

ZRange ChuckPlacement::body_range() const {
    const double a = z_at(0), b = z_at(inserted_length);
    return {std::min(a, b), std::max(a, b)};
}

bool ChuckPlacement::covers(double z, double theta) const {
    const double s = right ? core_length - z : z;  // from this chuck's core end
    constexpr double kEdge = 1e-9;
    for (const ExpandingElement& e : expanding) {
        if (std::abs(s - e.center) > e.width / 2 + kEdge) continue;
        if (e.segments == 0) return true;
        for (int k = 0; k < e.segments; ++k) {
            const double d = std::remainder(theta - 2 * M_PI * k / e.segments, 2 * M_PI);
            if (std::abs(d) <= e.segment_angle / 2 + kEdge) return true;
        }
    }
    return false;
}

ChuckPlacement chuck_placement(const Scene& scene, const ChuckSpec& chuck) {
    return {chuck.name,         chuck.name == "right", scene.core.length, chuck.inserted_length,
            chuck.shaft_length, chuck.expanding};
}

std::vector<Arc> contact_arcs(const ExpandingElement& e) {
    if (e.segments == 0) return {{0, 2 * M_PI}};
    std::vector<Arc> arcs;
    for (int k = 0; k < e.segments; ++k) {
        const double centre = 2 * M_PI * k / e.segments;
        arcs.push_back({centre - e.segment_angle / 2, centre + e.segment_angle / 2});
    }
    return arcs;
}

}  // namespace coremodal
