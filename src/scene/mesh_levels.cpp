#include "scene/mesh_levels.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace coremodal {

const MeshLevel* find_mesh_level(std::string_view name) {
    for (const MeshLevel& level : kMeshLevels)
        if (level.name == name) return &level;
    return nullptr;
}

std::optional<int> elements_along(double length, double outer_diameter, int n_around,
                                  double axial_aspect) {
    const double circumferential = std::numbers::pi * outer_diameter / n_around;
    const double n = std::ceil(length / (axial_aspect * circumferential));
    // Written so that NaN and infinity also land in the "too many" branch.
    if (!(n <= kMaxElementsAlong)) return std::nullopt;
    return std::max(kMinElementsAlong, static_cast<int>(n));
}

}  // namespace coremodal
