// The cell loop, independent of the matrix format: each cell's stiffness and
// mass are handed to an insertion callback with the cell's global dofs (-1 for
// eliminated ones). A unit test fills dense Eigen matrices with it; a run
// fills PETSc matrices (DOLFINx's pattern).
#pragma once

#include "assembly/dof_map.hpp"
#include "material/material.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace coremodal {

// Material of each mesh part (index as in Mesh::part_names).
struct PartMaterial {
    Matrix6 C_cylindrical;
    double density = 0;
};

// A contribution beyond the volume cells: springs between nodes or to the
// ground, point masses. Three DOFs per node, node-major like the cells.
struct CouplingElement {
    std::vector<int> nodes;
    Eigen::MatrixXd K, M;  // 3 n x 3 n (M may be empty: springs have no mass)
};

using CellInsert = std::function<void(const std::vector<int>& dofs, const Eigen::MatrixXd& K_cell,
                                      const Eigen::MatrixXd& M_cell)>;

// Loops over the cells for which `take(cell)` is true. Returns the mass of
// those cells (sum of rho * V), for the "mass equals rho V" check.
double assemble_cells(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                      const std::function<bool(int)>& take, const CellInsert& insert);

}  // namespace coremodal
