// A three-node Timoshenko beam element along the z axis, in 3D: 6 DOFs per
// node (Eigen only; docs/theory/beam.md, "The beam model level").
//
// Node DOFs, in this order: ux, uy, uz (m) and the rotation-vector components
// rx, ry, rz (rad, right hand). Without shear a section turns with the axis:
// ry = d ux/dz and rx = -d uy/dz, so the x-z plane bends in (ux, ry) and the
// y-z plane in (uy, -rx) with the same plane element.
//
// Weak forms, with w the deflection and phi the section rotation of a plane:
//   bending   int EI phi'^2 + kappa G A (w' - phi)^2 dz,  int rho A w^2 + rho I phi^2 dz
//   axial     int EA uz'^2 dz,                          int rho A uz^2 dz
//   torsion   int GJ rz'^2 dz,                          int rho J rz^2 dz
// Nodes at both ends and the middle; every motion is interpolated
// quadratically and on its own (Lagrange). Mass and bending: full 3-point
// Gauss integration (consistent mass, rotary inertia included); shear:
// 2-point reduced integration, which removes shear locking of slender
// elements. Eigenvalues converge as h^4. (A two-node element with
// "interdependent" shape functions, exact in statics, was tried and dropped:
// its shape functions turn linear as shear dominates small elements, and
// frequencies then converge only as h^2.)
#pragma once

#include "beam/beam_theory.hpp"

#include <Eigen/Dense>

namespace coremodal {

namespace beam_dof {
constexpr int ux = 0, uy = 1, uz = 2, rx = 3, ry = 4, rz = 5;
constexpr int per_node = 6;
}  // namespace beam_dof

constexpr int kElementNodes = 3;  // end, middle, end
constexpr int kElementDofs = kElementNodes * beam_dof::per_node;

using BeamElementMatrix = Eigen::Matrix<double, kElementDofs, kElementDofs>;

struct TimoshenkoElement {
    double length = 0;  // m, end to end (the middle node halfway)
    BeamSection section;
};

struct ElementMatrices {
    BeamElementMatrix K, M;
};
ElementMatrices element_matrices(const TimoshenkoElement& e);
// The shape function of each node at xi in [0, 1] (first end node to the
// last); every one of the six motions is interpolated with them.
Eigen::RowVector3d element_shape(double xi);

// One bending plane on (w, phi) of the three nodes: 6x6. Also the whole of
// the 2D Timoshenko beam of beam_theory.hpp.
using PlaneMatrix = Eigen::Matrix<double, 6, 6>;
PlaneMatrix plane_bending_stiffness(const TimoshenkoElement& e);
PlaneMatrix plane_bending_mass(const TimoshenkoElement& e);

}  // namespace coremodal
