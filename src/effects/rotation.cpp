#include "effects/rotation.hpp"

namespace coremodal {

std::vector<std::string> rotating_effect_names(const Scene& scene, const RotationSpec& rotation,
                                               bool level_has_centrifugal) {
    std::vector<std::string> out = scene.effects();
    out.push_back(Gyroscopic::kName);
    if (level_has_centrifugal && rotation.centrifugal_stiffening) out.push_back(CentrifugalStiffening::kName);
    return out;
}

}  // namespace coremodal
