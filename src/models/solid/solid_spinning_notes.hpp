// What the solid level's spinning model includes and leaves out, echoed
// in a Campbell diagram's notes (analyses/campbell).
#pragma once

#include "models/solid/rotating_solid.hpp"
#include "scene/rotation_spec.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The gyroscopic term (stationary frame) or the co-rotating coordinates,
// and the centrifugal stiffening with the rigid motions its static solve pinned.
std::vector<std::string> spinning_notes(const RotationSpec& rotation, const RotatingSolid& solid);

}  // namespace coremodal
