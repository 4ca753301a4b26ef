// What the model levels' forced responses (models/<level>/*_response.cpp)
// share: the result's fields that do not depend on the level, and the line
// on the modes kept.
#pragma once

#include "models/response/response_result.hpp"
#include "scene/model_choice.hpp"

#include <string>

namespace coremodal {

// A level's forced response: the level and the first of the result's
// notes, how it is computed and checked; held in the level's own file
// (beam_response.cpp, harmonic_response.cpp, solid_response.cpp).
struct ResponseLevel {
    ModelChoice level;
    const char* note;
};
extern const ResponseLevel kBeamResponse, kHarmonicResponse, kSolidResponse;

// The level-independent fields of the result (the range, probes, limit,
// damping as given, Dp, effects, notes and the setup's assumptions) and
// the level's note.
ResponseResult response_result_for(const Scene& scene, const ResponseSetup& setup, const ResponseLevel& level);

// "modes kept: 6 of 568 ... with the static part of the others" (the level's
// words for its modes, e.g. "lateral modes at rest").
std::string kept_modes_assumption(const ResponseChecks& checks, const std::string& modes_words);

}  // namespace coremodal
