// What the harmonic level's spinning model includes and leaves out, echoed
// in a Campbell diagram's notes (analyses/campbell).
#pragma once

#include "models/harmonic/rotating_harmonics.hpp"
#include "scene/rotation_spec.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The gyroscopic term of the bodies of revolution, the wave numbers swept,
// and the centrifugal prestress (its size at the top speed) or why not.
std::vector<std::string> spinning_notes(const RotationSpec& rotation, const RotatingHarmonics& harmonics);

}  // namespace coremodal
