// Ilomaki's I-5 safe web speeds (beam/speeds.hpp) as the analyses on a
// spinning roll report them beside their own speeds (campbell, response):
// one JSON shape and one wording for summary.json, report.md and the console.
#pragma once

#include "beam/speeds.hpp"

#include <toml++/toml.h>

#include <string>

namespace coremodal {

// {first_bending_at_rest_hz, dp_m, i5_safe_web_speed: [{factor, v_safe_m_s}]},
// or {not_given: why}.
toml::table i5_speeds_json(const RollSpeeds& speeds);

// "- I-5 safe web speed (factor 0.7, first bending at rest 26.308 Hz, Dp
// 202.1 mm): 11.69 m/s" per factor, or one line saying why there is none.
std::string i5_speed_lines(const RollSpeeds& speeds);

}  // namespace coremodal
