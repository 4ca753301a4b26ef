#include "scene/mesh_levels.hpp"

#include "common/error.hpp"
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
    const auto along = elements_along(scene.core.length, scene.core.outer_diameter, level->n_around, level->axial_aspect);
    if (!along) throw InputError("--mesh " + std::string(level_name) + ": too many elements along the core");
    scene.mesh.level = std::string(level->name);
    scene.mesh.n_wall = level->n_wall;
    scene.mesh.n_rest_paper = level->n_rest_paper;
    scene.mesh.n_around = level->n_around;
    scene.mesh.n_along = *along;
}

}  // namespace coremodal
