// [limits] of a case file (docs/how-to/limits.md): how fast a rest roll may run in
// its stand as it unwinds, one verdict over the rest-roll diameters
// (`coremodal limits`, analyses/limits). Like [response], the table is read
// beside the Scene, not into it: the case reader checks it with every other
// key, and `coremodal limits` reads it with parse_limits_case.
#pragma once

#include "scene/response_spec.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace coremodal {

// Rest-roll diameters the verdict is evaluated at by default (docs/how-to/limits.md).
inline constexpr int kDefaultLimitsPoints = 20;

struct LimitsSpec {
    // The rest-roll diameters, largest first: default the case's roll down
    // to the bare core. Checked against both by the reader.
    std::optional<double> largest_diameter_m, smallest_diameter_m;
    int points = kDefaultLimitsPoints;
    std::optional<double> target_web_speed_m_s;  // the press's speed: where must the roll be changed
    std::optional<double> limit_m;               // the amplitude limit ([response] limit, else +-5 mm)
    bool band = true;                            // propagate the uncertain inputs (docs/how-to/limits.md)
};

// The case at `path`, its response setup (none without [response]) and its
// [limits] (none without the table). Throws InputError as parse_case_file does.
struct LimitsCase {
    Scene scene;
    std::optional<ResponseSetup> response;
    std::optional<LimitsSpec> limits;
};
LimitsCase parse_limits_case(const std::string& path);
LimitsCase parse_limits_case_text(std::string_view text, const std::string& path);

}  // namespace coremodal
