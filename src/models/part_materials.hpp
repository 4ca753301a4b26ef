// The material of each part of a mesh or section, from the scene.
#pragma once

#include "assembly/cell_loop.hpp"  // PartMaterial
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The material of each named part ("core", "rest_paper", "chuck_<name>");
// InputError naming `source` for a part the case file gives no material.
std::vector<PartMaterial> part_materials(const Scene& scene, const std::vector<std::string>& part_names,
                                         const std::string& source);

}  // namespace coremodal
