// What the solid level's spinning model includes and leaves out, echoed
// in a Campbell diagram's notes (analyses/campbell).
#include "models/solid/solid_spinning_notes.hpp"

#include "common/format.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

std::vector<std::string> spinning_notes(const RotationSpec& rotation, const RotatingSolid& solid) {
    std::vector<std::string> notes;
    if (solid.rotating_frame())
        notes.push_back(
            "rotation at the solid level in co-rotating coordinates (the scene is not a body of revolution; its "
            "non-spinning parts look the same from every angle): M q'' + Omega G_c q' + (K + Omega^2 (K_sigma1 - "
            "M_P)) q = 0, the Coriolis term G_c = 2 int rho N^T (e_z x) N dV and the spin softening M_P over every "
            "mass; each mode's rotating-frame frequency f is brought to the stationary frame by the dominant "
            "circumferential harmonic k of its shape on the roll's surface: f_stat = |f - k f_rot|, forward when "
            "-k (f - k f_rot) > 0 (docs/theory/rotation-solid.md)");
    else
        notes.push_back(
            "rotation at the solid level: the gyroscopic term of every spinning cell (core, rest paper, chuck bodies "
            "and shafts: the material carried through the stationary frame at Omega d/dtheta, the harmonic level's "
            "term on the hexahedra); spring layers, bearings and frames do not spin");
    if (!rotation.centrifugal_stiffening && solid.rotating_frame()) {
        notes.push_back(
            "[rotation] centrifugal_stiffening = false: the centrifugal prestress's stiffness K_sigma1 "
            "is left out; the spin softening M_P stays (part of the change of coordinates)");
        return notes;
    }
    if (!rotation.centrifugal_stiffening) {
        notes.push_back(
            "[rotation] centrifugal_stiffening = false: the terms of order Omega^2 (the centrifugal "
            "prestress and the convective spin softening) are left out");
        return notes;
    }
    std::string pinned;
    for (const std::string& p : solid.pinned_rigid_motions()) pinned += (pinned.empty() ? "" : ", ") + p;
    notes.push_back(std::string("centrifugal stiffening at the solid level: Omega^2 ") +
                    (solid.rotating_frame() ? "K_sigma1 on every spinning cell"
                                            : "K_Omega on every spinning cell, K_Omega = "
                                              "K_sigma1 - M_L (effects/rotation.hpp)") +
                    ": the geometric stiffness of the stress of a static solve "
                    "under the centrifugal load rho r e_r per unit Omega^2 (the scene's supports; stresses at the "
                    "integration points, the material turned per point)" +
                    (solid.rotating_frame() ? "" : ", less the convective spin softening") +
                    "; linear in the prestress (sigma = Omega^2 sigma1)" +
                    (pinned.empty() ? std::string()
                                    : "; the static solve pinned one DOF for each rigid motion the supports leave "
                                      "free (" +
                                          pinned + "), on which the load does no work"));
    return notes;
}

}  // namespace coremodal
