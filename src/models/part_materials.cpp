#include "models/part_materials.hpp"

#include "common/error.hpp"
#include "material/material.hpp"

namespace coremodal {

std::vector<PartMaterial> part_materials(const Scene& scene, const std::vector<std::string>& part_names,
                                         const std::string& source) {
    std::vector<PartMaterial> materials;
    for (const auto& part : part_names) {
        const OrthotropicMaterial* m = nullptr;
        if (part == "core") m = &scene.core.material;
        if (part == "rest_paper" && scene.rest_paper) m = &scene.rest_paper->material;
        for (const auto& c : scene.supports.chucks)
            if (part == "chuck_" + c.name) m = &c.material;
        if (!m)
            throw InputError(source + ": mesh part '" + part + "' has no material in the case file; parts are "
                             "'core' and (with a [rest_paper] table) 'rest_paper'");
        materials.push_back({stiffness_cylindrical(*m), m->density});
    }
    return materials;
}

}  // namespace coremodal
