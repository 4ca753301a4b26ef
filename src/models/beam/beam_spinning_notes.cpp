// What the beam level's spinning model includes and leaves out, echoed
// in a Campbell diagram's notes (analyses/campbell).
#include "models/beam/beam_spinning_notes.hpp"

#include "common/format.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

std::vector<std::string> spinning_notes(const RotationSpec& rotation) {
    std::vector<std::string> notes{
        "rotation at the beam level: the gyroscopic term of every spinning beam (core with rest paper, chuck bodies "
        "and shafts; polar inertia rho_J per length); bearings and frames do not spin"};
    if (rotation.centrifugal_stiffening)
        notes.push_back(
            "[rotation] centrifugal_stiffening = true: not included at the beam level, which has no term for it (the "
            "hoop prestress of a spinning roll stiffens its section's ovalling, not its bending; zero in beam theory)");
    return notes;
}

}  // namespace coremodal
