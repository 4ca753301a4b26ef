#include "analyses/response/response.hpp"

#include "models/choose.hpp"
#include "models/response/level_response.hpp"

namespace coremodal {

// The scene's level hands out its response model (ModelLevel::response);
// require_response_level refused a scene the level cannot take.
ResponseResult run_forced_response(const Scene& scene, const ResponseSetup& setup, const BeamModelOptions& options,
                                   ResponseChecking checking, RestModes rest) {
    require_response_level(scene);
    return make_model_level(scene)->response(scene, options)->respond(setup, checking, rest);
}

std::vector<ResponseResult> run_forced_responses(const Scene& scene, const std::vector<ResponseSetup>& setups,
                                                 ResponseChecking checking, RestModes rest) {
    require_response_level(scene);
    return make_model_level(scene)->response(scene, {})->respond_all(setups, checking, rest);
}

}  // namespace coremodal
