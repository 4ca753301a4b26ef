#include "scene/mesh_levels.hpp"

#include "common/error.hpp"
#include "scene/mesh_rule.hpp"
#include "scene/scene.hpp"

#include <string>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace coremodal {

const MeshLevel* find_mesh_level(std::string_view name) {
    for (const MeshLevel& level : kMeshLevels)
        if (level.name == name) return &level;
    return nullptr;
}

int elements_around(const MeshLevel& level, double inner_diameter, double outer_diameter) {
    const double mean_radius = (inner_diameter + outer_diameter) / 4, wall = (outer_diameter - inner_diameter) / 2;
    const double wanted = level.around_per_slenderness * 2 * std::numbers::pi * std::sqrt(mean_radius / wall);
    // Written so that NaN (a wall the case reader refuses) keeps the level's count.
    if (!(wall > 0) || !(wanted > level.n_around)) return level.n_around;
    return 4 * static_cast<int>(std::ceil(std::min<double>(wanted, kMaxLevelElementsAround) / 4));
}

std::optional<int> elements_along(double length, double outer_diameter, int n_around,
                                  double axial_aspect) {
    const double circumferential = std::numbers::pi * outer_diameter / n_around;
    const double n = std::ceil(length / (axial_aspect * circumferential));
    // Written so that NaN and infinity also land in the "too many" branch.
    if (!(n <= kMaxElementsAlong)) return std::nullopt;
    return std::max(kMinElementsAlong, static_cast<int>(n));
}

void apply_mesh_level(Scene& scene, std::string_view level_name) {
    const MeshLevel* level = find_mesh_level(level_name);
    if (!level) {
        std::string names;
        for (const MeshLevel& l : kMeshLevels) names += (names.empty() ? "" : ", ") + std::string(l.name);
        throw InputError("--mesh " + std::string(level_name) + ": unknown mesh level; expected one of " + names);
    }
    if (scene.mesh.file)
        throw InputError("--mesh " + std::string(level_name) + ": the case uses the mesh file " + *scene.mesh.file +
                         "; a mesh level applies only to generated meshes");
    // The level's counts, raised where the band needs more (scene/mesh_rule.hpp).
    const MeshRule rule = mesh_rule(scene, level_target_error(*level));
    const int around =
        std::max(elements_around(*level, scene.core.inner_diameter, scene.core.outer_diameter), rule.around);
    const auto along = elements_along(scene.core.length, scene.core.outer_diameter, around, level->axial_aspect);
    if (!along) throw InputError("--mesh " + std::string(level_name) + ": too many elements along the core");
    scene.mesh.level = std::string(level->name);
    scene.mesh.n_wall = level->n_wall;
    scene.mesh.n_rest_paper = level->n_rest_paper;
    scene.mesh.n_around = around;
    scene.mesh.n_along = std::max(*along, rule.along);
}

}  // namespace coremodal
