// [rotation] of a case file (docs/how-to/campbell.md): the roll, its chucks and
// shafts spin about the z axis. One speed: the modes at that speed (`run`);
// several: a Campbell sweep (`coremodal campbell`). Like [study] and
// [calibration], the table is read beside the Scene, not into it: the case
// reader checks it with every other key (every command refuses a wrong one),
// and the commands that simulate rotation read it with parse_case_rotation.
#pragma once

#include "scene/scene.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

// Speeds are rotation frequencies f_rot in Hz; a web speed v is converted
// with f_rot = v / (pi Dp), Dp the roll's outer diameter (roll_outer_diameter).
struct RotationSpec {
    std::vector<double> speeds_hz;  // ascending, >= 0; one value or a sweep
    bool from_web_speed = false;    // the file gave web speeds
    std::vector<int> excitation_orders = {1, 2};  // k in f = k f_rot: lines drawn, crossings reported
    // The steady centrifugal stress as geometric stiffness, where a level
    // has a term for it (none at the beam level: docs/theory/rotation.md).
    bool centrifugal_stiffening = true;
    // operating_speeds: the speeds the machine runs at, [lowest, highest] in
    // Hz, inside the sweep (a critical speed is only known there); or none.
    std::optional<std::array<double, 2>> operating_hz;
    bool sweep() const { return speeds_hz.size() > 1; }
};

// Dp: the rest paper's outer diameter, or the core's without rest paper, m.
double roll_outer_diameter(const Scene& scene);

// The case at `path` and its [rotation] (none without the table). Throws
// InputError as parse_case_file does.
struct RotatingCase {
    Scene scene;
    std::optional<RotationSpec> rotation;
};
RotatingCase parse_rotating_case(const std::string& path);
RotatingCase parse_rotating_case_text(std::string_view text, const std::string& path);

}  // namespace coremodal
