// Shape functions of the quadratic cells in gmsh node ordering.
//   hex20: serendipity on [-1, 1]^3 (gmsh type 17)
//   hex27: triquadratic Lagrange on [-1, 1]^3 (gmsh type 12)
//   tet10: quadratic Lagrange on the unit tet (gmsh type 11)
// Node reference coordinates are gmsh's localNodeCoord tables
// (gmsh::model::mesh::getElementProperties), so a cell read from gmsh can be
// handed to the kernels without reordering.
#pragma once

#include "element/element.hpp"

#include <Eigen/Dense>

namespace coremodal {

using ReferenceCoords = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Reference coordinates of the nodes, one row per node, gmsh order.
const ReferenceCoords& reference_node_coords(CellType type);

// N(a) at reference point xi.
Eigen::VectorXd shape_values(CellType type, const Eigen::Vector3d& xi);

// dN(a, j) = d N_a / d xi_j at reference point xi.
Eigen::Matrix<double, Eigen::Dynamic, 3> shape_gradients(CellType type, const Eigen::Vector3d& xi);

// 1D quadratic Lagrange function on the nodes {-1, 0, 1}, for the node at c
// (its sign picks the node), and its derivative at x.
void lagrange_1d(double x, double c, double& value, double& derivative);

}  // namespace coremodal
