// Element kernels of the centrifugal term of a spinning cell
// (effects/rotation.hpp states the physics once): the centrifugal body force
// per unit Omega^2, the stress of its static solution at the integration
// points, and the two parts of K_Omega = K_sigma1 - M_L.
//
// Weak forms, per cell Ve, every matrix per unit Omega^2 and expanded by the
// 3x3 identity (each acts on every Cartesian displacement component alike):
//   f1_a      = int_Ve rho N_a (x, y, 0) dV                 (centrifugal load)
//   K_sigma1  = int_Ve (grad N) sigma1 (grad N)^T dV (x) I3  (its stress's geometric stiffness)
//   M_L       = int_Ve rho (dN/dtheta)(dN/dtheta)^T dV (x) I3, d/dtheta = x d/dy - y d/dx
//                                                         (the convective spin softening)
// with sigma1 = C(x) eps(u1) (Cartesian, C the cylindrical stiffness turned
// to the point's polar angle as element_matrices does). Same quadrature and
// Jacobian check as element_matrices; node-major DOFs (dof 3a + c).
#pragma once

#include "element/element.hpp"

#include <Eigen/Dense>

#include <vector>

namespace coremodal {

// The stress at one integration point: where it is and the Cartesian tensor (Pa per unit Omega^2).
struct PointStress {
    Eigen::Vector3d x;
    Eigen::Matrix3d sigma;
};

// f1 (3n), N per unit Omega^2 (rad/s)^2: the consistent centrifugal body force rho r e_r.
Eigen::VectorXd element_centrifugal_load(CellType type, const CellCoords& coords, double density);

// sigma = C(x) eps(u) at each integration point of the full rule, u the
// cell's 3n nodal displacements (node-major).
std::vector<PointStress> element_stresses(CellType type, const CellCoords& coords, const Matrix6& C_cylindrical,
                                          const Eigen::VectorXd& u);

// K_sigma1 (3n x 3n) of the stresses at the integration points (as
// element_stresses returns them, same order).
Eigen::MatrixXd element_stress_stiffness(CellType type, const CellCoords& coords,
                                         const std::vector<PointStress>& stresses);

// M_L (3n x 3n): the stationary frame's convective spin softening.
Eigen::MatrixXd element_spin_softening(CellType type, const CellCoords& coords, double density);

// K_Omega = K_sigma1 - M_L of a cell whose static centrifugal displacement
// (per unit Omega^2) is u1 (3n, node-major).
Eigen::MatrixXd element_centrifugal(CellType type, const CellCoords& coords, const Matrix6& C_cylindrical,
                                    double density, const Eigen::VectorXd& u1);

}  // namespace coremodal
