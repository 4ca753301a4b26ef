// What the beam level's spinning model includes and leaves out, echoed
// in a Campbell diagram's notes (analyses/campbell).
#pragma once

#include "scene/rotation_spec.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The beam level's gyroscopic terms, and the centrifugal stiffening it has no term for.
std::vector<std::string> spinning_notes(const RotationSpec& rotation);

}  // namespace coremodal
