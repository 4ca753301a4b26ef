// The paper web ([web], docs/theory/web.md): the web leaves the roll along one line
// of its outer surface towards the first guide roller, a free span s away,
// under the tension T per unit width. For the roll's small vibrations the
// span acts on that line, per unit length of roll, as three springs:
//
//   along the web (d):          k_d = E t / s        the web's own stretch
//   across it (n, out of its plane): k_n = T / s     a string under T
//   along the roll's axis (z):  k_z = (G t + T) / s  the web's in-plane shear, and T turning in its plane
//
// E, G the web's in-plane modulus along its length and its shear modulus, t
// its thickness. Left out, with the reason (numbers for the example case in
// docs/theory/web.md): the web's bending stiffness (a sheet), the span's own mass
// (rho t s / 3 per unit length against the roll's hundreds of times more),
// and the tension's static pull T on the roll (a steady side load: it bends
// the roll but does not change its stiffness to first order).
//
// Where the line is: the roll unwinds turning about +z (as [rotation] spins
// it), so its surface pays the web out along d = (cos a, sin a) from the
// tangent point p = R (sin a, -cos a), where e_z x p / R = d. A turn rz of
// the section moves that point by rz e_z x p = R rz d: along the web, so the
// web also holds the roll's torsion.
#pragma once

#include "material/material.hpp"  // Matrix6
#include "scene/scene.hpp"
#include "scene/web_springs.hpp"

#include <Eigen/Dense>

namespace coremodal {

// The springs themselves (k_d, k_n, k_z), the shear modulus's default and
// the run's assumptions about them: scene/web_springs.hpp.
struct PaperWeb {
    static constexpr const char* kName = "web";
};

// The web's direction d, the unit normal n out of its plane (from the axis
// to the tangent point: p = R n), both in the x-y plane.
Eigen::Vector3d web_direction(const WebSpec& web);
Eigen::Vector3d web_tangent_normal(const WebSpec& web);

// The three springs per unit length of roll on the displacement of the
// surface line, N/m^2, in global (x, y, z): k_d d d^T + k_n n n^T + k_z e_z e_z^T.
Eigen::Matrix3d web_line_stiffness(const WebSpec& web);

// The same on a beam section's six DOFs (ux, uy, uz, rx, ry, rz) at the
// roll's axis, the line at radius R: the surface point moves by u + r x p,
// so K6 = A^T K_line A with A = [I, -[p]x].
Matrix6 web_beam_stiffness_per_length(const WebSpec& web, double radius);

}  // namespace coremodal
