#include "scene/scene.hpp"

namespace coremodal {

// The vocabulary of effects is shared with the summary and the result file:
// "core" always, "rest_paper" when the scene has one, "rigid_clamps" for a
// clamped support. A free-free scene adds nothing: free is the absence of supports.
std::vector<std::string> Scene::effects() const {
    std::vector<std::string> out{"core"};
    if (rest_paper) out.push_back("rest_paper");
    if (supports.kind == SupportKind::clamped) out.push_back("rigid_clamps");
    return out;
}

}  // namespace coremodal
