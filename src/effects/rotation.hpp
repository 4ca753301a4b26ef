// Rotation ([rotation], docs/rotation.md), stated once for every model level.
// In the stationary frame the roll, its chuck bodies and shafts spin at
// Omega = 2 pi f_rot about the z axis; the bearings, frames and the stand do
// not. A spinning part adds the gyroscopic term Omega G (element/term.hpp):
//
//     M q'' + Omega G q' + (K + K_sigma(Omega^2)) q = 0
//
//   effect                  solid                 harmonic              beam (beam/rotating_modes)
//   gyroscopic              every cell            every section cell    rho_J per length on (rx, ry) of every beam
//                           (element_gyroscopic;  (harmonic_quad8_spin_
//                           bodies of revolution) coupling)
//   centrifugal_stiffening  not yet               not yet               none: no term in beam theory (see below)
//
// The solid and harmonic levels' term is one: the material passes through
// each point of the stationary frame at Omega d/dtheta, and the kinetic
// energy's cross term Omega int rho u'.du/dtheta dV gives G (on a rigid tilt
// of a section it is the beam's rho_J, tested on both elements).
//
// The beam's gyroscopic term: a section of polar inertia rho_J per length
// spinning at Omega and tilted by (rx, ry) has the angular momentum
// rho_J Omega (ry, -rx, 1) + rho_I (rx', ry', 0); its rate gives the moments
// per length rho_I rx'' + Omega rho_J ry' and rho_I ry'' - Omega rho_J rx', so
// G per length is rho_J [[0, 1], [-1, 0]] on (rx, ry): skew-symmetric.
//
// Centrifugal stiffening: a roll spinning about its own axis carries a steady
// hoop and radial stress; it stiffens the section against ovalling (n >= 2
// at the harmonic and solid levels) but does no work in a beam's bending,
// stretching or twisting, so the beam level has no term for it (exactly
// zero in Rayleigh and Timoshenko beam theory). It is reported as not
// included when the scene asks for it at a level without the term.
#pragma once

#include "element/term.hpp"
#include "scene/rotation_spec.hpp"
#include "scene/scene.hpp"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace coremodal {

struct Gyroscopic {
    static constexpr const char* kName = "gyroscopic";
    static constexpr Term kTerm = Term::gyroscopic;
    // G per unit length on (rx, ry) of a spinning beam of polar inertia rho_J (kg m).
    static Eigen::Matrix2d per_length(double rho_J) {
        Eigen::Matrix2d g;
        g << 0, rho_J, -rho_J, 0;
        return g;
    }
};

struct CentrifugalStiffening {
    static constexpr const char* kName = "centrifugal_stiffening";
    static constexpr Term kTerm = Term::geometric_stiffness;
};

// The web speed of a rotation frequency at the roll's outer diameter: v = pi Dp f.
inline double web_speed(double f_rot_hz, double roll_outer_diameter) { return M_PI * roll_outer_diameter * f_rot_hz; }

// The effects of a spinning scene, in the summary's vocabulary: the scene's
// (Scene::effects) then "gyroscopic"; centrifugal stiffening only where the
// level has the term (`level_has_centrifugal`), which none has yet.
std::vector<std::string> rotating_effect_names(const Scene& scene, const RotationSpec& rotation,
                                               bool level_has_centrifugal = false);

}  // namespace coremodal
