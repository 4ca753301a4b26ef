// A case file's [traction] table: one roller under the web (Rice & Gans,
// docs/how-to/traction.md), read through the case reader like every other table
// (scene/case_reader_traction.cpp): keys, units and ranges from
// scene/case_keys.cpp, errors "FILE:LINE:COL: [traction] wrap = -5 deg
// must be positive".
//
// Two kinds of file hold it: a file for `coremodal traction` alone (only
// name, description and [traction]), and a stand scene, where [traction]
// sits beside [core], [web] and the rest; such a file is checked as a whole
// and every other command ignores [traction].
//
// For the limits command: read_traction_case(path) gives the roller of a
// scene (nullopt when it has none); traction/traction_model.hpp's
// zero_traction_speed(spec) is the web speed at which the web no longer
// touches it, slip_speed(spec, needed) the speed at which it can no longer
// carry a tension difference.
#pragma once

#include "traction/traction_model.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

struct TractionCase {
    std::string name, description, source_file;
    TractionSpec spec;
    bool speeds_given = false;  // false: web_speeds are the default range (0 to 1.25 x zero-traction speed)
    bool has_roll = false;      // the file is a stand scene too ([core] and the rest, checked)
    // The defaults in use, each with its source ("[traction] air_viscosity =
    // 1.81e-05 Pa*s (Rice & Gans, Table 3: air at room temperature)").
    std::vector<std::string> assumptions;
    // Values that look like unit slips (said on stderr, listed in the report).
    std::vector<std::string> warnings;
};

// The default speed range when the file gives none: 0 to this factor times
// the zero-traction speed, so that the curve shows its whole fall and the
// floating web beyond; kDefaultSpeedPoints points.
inline constexpr double kDefaultSpeedSpan = 1.25;
inline constexpr int kDefaultSpeedPoints = 51;

// The file's [traction], or nullopt when it has none. Throws InputError on
// any problem in the file (all of it when it describes a roll too).
std::optional<TractionCase> read_traction_case(const std::string& path);
std::optional<TractionCase> read_traction_case_text(std::string_view text, const std::string& path);

}  // namespace coremodal
