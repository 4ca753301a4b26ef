// Element kernels: coordinates and material in, element matrices out.
// Plain Eigen; no PETSc, gmsh or MPI here.
//
// Weak form (linear elasticity, small strain):
//   K_e = int_Ve B^T C(x) B dV,   M_e = int_Ve rho N^T N dV  (consistent mass),
// with C(x) the cylindrical stiffness rotated to global axes at each
// integration point (polar angle of that point about the z axis).
// Node ordering is gmsh's for each cell type; DOF order is node-major:
// dof 3a + c is component c (x, y, z) of node a.
#pragma once

#include "material/material.hpp"

#include <Eigen/Dense>

namespace coremodal {

enum class CellType { hex20, hex27, tet10 };

int nodes_per_cell(CellType type);
const char* cell_type_name(CellType type);  // "hex20", "hex27", "tet10"

// coords: nodes_per_cell rows x 3 columns, metres.
using CellCoords = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Fills K and M (resized to 3n x 3n). Full integration: 3x3x3 Gauss for hex,
// a degree-4-exact rule for tet10 (mass is degree 4). Throws
// std::runtime_error naming the cell if the Jacobian is not positive at an
// integration point (inverted or badly distorted cell).
void element_matrices(CellType type, const CellCoords& coords, const Matrix6& C_cylindrical,
                      double density, Eigen::MatrixXd& K, Eigen::MatrixXd& M);

// The gyroscopic matrix G_e (3n x 3n, per unit spin speed in rad/s) of a cell
// of a body of revolution spinning about the z axis, seen from the stationary
// frame (effects/rotation.hpp, docs/theory/rotation-solid.md). The material passes through
// each point at Omega d/dtheta, d/dtheta = x d/dy - y d/dx acting on every
// Cartesian component, so its velocity is u' + Omega du/dtheta and the kinetic
// energy's cross term is Omega q'^T C q with
//   C = c (x) I3,   c_ab = int_Ve rho N_a (x dN_b/dy - y dN_b/dx) dV;
// Lagrange's equations of that term give Omega (C - C^T) q', so
//   G_e = (c - c^T) (x) I3,   skew-symmetric,
// the term M q'' + Omega G q' + K q = 0 of every level (the harmonic level's
// L on the section; a rigid tilt's rho J of the beam's). This is not the
// rotating frame's Coriolis matrix 2 int rho N^T S N dV (S the rotation by
// 90 degrees about z): that one describes motion seen from axes turning with
// the body, whose frequencies differ from the stationary ones by about
// +-n Omega and which needs the Omega^2 spin softening to be consistent.
// Same quadrature and Jacobian check as element_matrices.
Eigen::MatrixXd element_gyroscopic(CellType type, const CellCoords& coords, double density);

// Volume of the cell (m^3), by the same quadrature.
double element_volume(CellType type, const CellCoords& coords);

}  // namespace coremodal
