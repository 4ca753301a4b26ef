// The model levels' forced responses, which run_forced_response
// (response.cpp) dispatches to, and what they share: the result's fields
// that do not depend on the level, and the line on the modes kept.
#pragma once

#include "analyses/response/response.hpp"

#include <string>

namespace coremodal {

// The level-independent fields of the result: the range, probes, limit,
// damping as given, Dp, effects, notes and the setup's assumptions.
ResponseResult response_result_for(const Scene& scene, const ResponseSetup& setup, const std::string& level);

// "modes kept: 6 of 568 ... with the static part of the others" (the level's
// words for its modes, e.g. "lateral modes at rest").
std::string kept_modes_assumption(const ResponseChecks& checks, const std::string& modes_words);

ResponseResult run_beam_response(const Scene& scene, const ResponseSetup& setup, const BeamModelOptions& options,
                                 ResponseChecking checking);
ResponseResult run_harmonic_response(const Scene& scene, const ResponseSetup& setup, ResponseChecking checking);
ResponseResult run_solid_response(const Scene& scene, const ResponseSetup& setup, ResponseChecking checking);

}  // namespace coremodal
