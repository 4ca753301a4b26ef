// What the harmonic level's spinning model includes and leaves out, echoed
// in a Campbell diagram's notes (analyses/campbell).
#include "models/harmonic/harmonic_spinning_notes.hpp"

#include "common/format.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

namespace {

// The largest hoop and radial stress of the prestress at the sweep's top speed, MPa.
std::string prestress_size(const CentrifugalPrestress& p, const RotationSpec& rotation) {
    double hoop = 0, radial = 0;
    for (const SectionStress& s : p.stress) {
        hoop = std::max(hoop, s.row(1).cwiseAbs().maxCoeff());
        radial = std::max(radial, s.row(0).cwiseAbs().maxCoeff());
    }
    const double spin = 2 * M_PI * rotation.speeds_hz.back(), mpa = spin * spin / 1e6;
    return "at " + significant(rotation.speeds_hz.back() * 60) + " rpm the largest hoop stress is " +
           significant(hoop * mpa) + " MPa and the largest radial stress " + significant(radial * mpa) + " MPa";
}

}  // namespace

std::vector<std::string> spinning_notes(const RotationSpec& rotation, const RotatingHarmonics& harmonics) {
    std::string ns;
    for (int n : harmonics.wave_numbers()) ns += (ns.empty() ? "" : ", ") + std::to_string(n);
    std::vector<std::string> notes{
        "rotation at the harmonic level: the gyroscopic term of every spinning body of revolution (core, rest paper, "
        "chuck bodies and shafts: the material carried through the stationary frame at Omega d/dtheta, which couples "
        "the two families of each wave number n >= 1 into forward and backward travelling waves); bearings and "
        "frames do not spin; wave numbers n = " +
        ns + ", chosen at rest"};
    if (const CentrifugalPrestress* p = harmonics.prestress())
        notes.push_back(
            "centrifugal stiffening: the steady stress of the spinning section (an axisymmetric static "
            "solve under the body force rho Omega^2 r with the scene's supports; " +
            prestress_size(*p, rotation) +
            ") as geometric stiffness, with the convective softening -Omega^2 rho |du/dtheta|^2 that "
            "goes with it in the stationary frame (effects/rotation.hpp)");
    else
        notes.push_back(
            "terms of order Omega^2 not included ([rotation] centrifugal_stiffening = false): the "
            "centrifugal prestress and the convective softening are left out together (they balance "
            "in part; a gyroscopic model to first order in Omega, as the beam level's)");
    return notes;
}

}  // namespace coremodal
