// A level's forced response (`coremodal response`, `limits`, `study`;
// analyses/response): what ModelLevel::response hands out for a scene. The
// beam's in models/beam/beam_response.cpp, the harmonic level's in
// models/harmonic/harmonic_response.cpp, the solid's in
// models/solid/solid_response.cpp; analyses/response drives it and never
// names a level.
#pragma once

#include "models/response/response_result.hpp"

#include <vector>

namespace coremodal {

class LevelResponse {
public:
    virtual ~LevelResponse() = default;
    // The steady response to one setup (steps 1-5 of analyses/response/response.hpp).
    virtual ResponseResult respond(const ResponseSetup& setup, ResponseChecking checking, RestModes rest) = 0;
    // Setups that differ only in what changes neither K nor M: by default one
    // after another; a level that can answers them all from one set of modes
    // at rest (the harmonic level's n = 1 basis, its labels and K's factor).
    virtual std::vector<ResponseResult> respond_all(const std::vector<ResponseSetup>& setups, ResponseChecking checking,
                                                    RestModes rest);
};

}  // namespace coremodal
