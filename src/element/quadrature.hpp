// Quadrature rules on the reference cells of element.hpp:
//   hex: [-1, 1]^3, tet: {xi, eta, zeta >= 0, xi + eta + zeta <= 1}.
// Weights sum to the reference volume (8 for the hex, 1/6 for the tet).
#pragma once

#include "element/element.hpp"

#include <Eigen/Dense>
#include <vector>

namespace coremodal {

struct QuadratureRule {
    std::vector<Eigen::Vector3d> points;  // reference coordinates
    std::vector<double> weights;
    int size() const { return static_cast<int>(weights.size()); }
};

// Tensor-product 3-point Gauss-Legendre: exact to degree 5 per direction,
// which is full integration of quadratic hex stiffness and mass on
// parallelepipeds (27 points).
QuadratureRule gauss_hex_3x3x3();

// Symmetric 14-point rule, exact to total degree 5 with all weights positive
// (Walkington): covers the degree-4 consistent mass of tet10 with one to
// spare, and positive weights keep the mass matrix positive definite.
QuadratureRule tet_degree5_14_point();

// The full-integration rule element_matrices uses for this cell type.
const QuadratureRule& full_integration_rule(CellType type);

}  // namespace coremodal
