// Ilomaki's I-5 safe web speeds (beam/speeds.hpp) as the analyses on a
// spinning roll report them beside their own speeds (campbell, response):
// one wording for report.md and the console (summary.json: safe_web_speed_json,
// output/summary_json.hpp).
#pragma once

#include "beam/speeds.hpp"

#include <string>

namespace coremodal {

// "- I-5 safe web speed (factor 0.7, first bending at rest 26.308 Hz, Dp
// 202.1 mm): 11.69 m/s" per factor, or one line saying why there is none.
std::string i5_speed_lines(const RollSpeeds& speeds);

}  // namespace coremodal
