// Rotation ([rotation], docs/theory/rotation.md), stated once for every model level.
// In the stationary frame the roll, its chuck bodies and shafts spin at
// Omega = 2 pi f_rot about the z axis; the bearings, frames and the stand do
// not. A spinning part adds the gyroscopic term Omega G and the centrifugal
// term Omega^2 K_Omega (element/term.hpp):
//
//     M q'' + Omega G q' + (K + Omega^2 K_Omega) q = 0
//
//   effect                  solid                 harmonic                  beam (beam/rotating_modes)
//   gyroscopic              every cell            every section cell        rho_J per length on (rx, ry)
//                           (element_gyroscopic;  (harmonic_quad8_spin_     of every beam
//                           bodies of revolution) coupling)
//   centrifugal_stiffening  every cell            every section cell        none: no term in beam theory
//                                                 (harmonic_quad8_          (see below)
//                                                 centrifugal)
//
// Where both terms come from. A spinning part's material at the stationary
// point x moves at Omega d/dtheta; its perturbation u (Cartesian components,
// in the stationary frame) is seen by the material as u rotated back, so the
// co-rotating equations rho (u_tt + 2 Omega e_z x u_t - Omega^2 P u) = div
// sigma(u) + div(sigma_0 grad u) (Coriolis, spin softening with P the
// projection on the x-y plane, and the steady centrifugal stress sigma_0's
// geometric stiffness) become, with d/dt -> d/dt + Omega d/dtheta and
// L = d/dtheta of the Cartesian components (= d/dtheta + e_z x on
// cylindrical ones; L^2 = d^2/dtheta^2 + 2 e_z x d/dtheta - P):
//
//     rho (u_tt + 2 Omega L u_t + Omega^2 L^2 u) = div sigma(u) + div(sigma_0 grad u)
//
// L is skew over a body of revolution, so G = 2 int rho N^T L N dV (skew) and
// the Omega^2 terms are K_Omega = K_sigma1 - M_L, M_L = int rho (L N)^T (L N) dV
// (the convective softening) and K_sigma1 = int grad N^T sigma_1 grad N dV
// (per displacement component), sigma_1 the stress of the static solve
// K u_1 = f_1 under the centrifugal body force rho r e_r per unit Omega^2
// (sigma_0 = Omega^2 sigma_1, linear). Checks: on a rigid translation L u = 0
// and grad u = 0, so K_Omega does nothing (a Jeffcott rotor's whirl has no
// Omega^2 term in the stationary frame); on a rigid tilt of a free body of
// revolution the two parts cancel (int sigma_1,yy dV = int rho y^2 dV by the
// virial of the static solve, against int rho x^2 dV from M_L); on a thin
// free ring they cancel for every inextensional wave n (sigma_1,tt = rho R^2),
// leaving Bryan's split exactly: omega = sqrt(omega_0^2 + beta^2 Omega^2)
// +- beta Omega, beta = n (n^2 - 1) / (n^2 + 1).
//
// The beam's gyroscopic term: a section of polar inertia rho_J per length
// spinning at Omega and tilted by (rx, ry) has the angular momentum
// rho_J Omega (ry, -rx, 1) + rho_I (rx', ry', 0); its rate gives the moments
// per length rho_I rx'' + Omega rho_J ry' and rho_I ry'' - Omega rho_J rx', so
// G per length is rho_J [[0, 1], [-1, 0]] on (rx, ry): skew-symmetric.
//
// Centrifugal stiffening at the beam level: a roll spinning about its own
// axis carries a steady hoop and radial stress; it stiffens the section
// against ovalling (n >= 2) but does no work in a beam's bending, stretching
// or twisting (the rigid-tilt cancellation above, section by section), so
// the beam level has no term for it (exactly zero in Rayleigh and Timoshenko
// beam theory). It is reported as not included when the scene asks for it
// at a level without the term.
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
// level has the term (`level_has_centrifugal`: harmonic and solid) and the
// scene asks for it.
std::vector<std::string> rotating_effect_names(const Scene& scene, const RotationSpec& rotation,
                                               bool level_has_centrifugal = false);

}  // namespace coremodal
