// The cell loop, independent of the matrix format: each cell's named terms
// (stiffness, mass; the gyroscopic term of a spinning scene) are handed to an
// insertion callback with the cell's global dofs (-1 for eliminated ones). A
// unit test fills dense Eigen matrices with it
// (tests/unit/assembly/test_cell_loop.cpp); a run fills PETSc matrices
// (DOLFINx's pattern).
#pragma once

#include "assembly/dof_map.hpp"
#include "element/term.hpp"
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

// One term's dense matrix over an element's DOFs (three per node, node-major).
struct TermMatrix {
    Term term;
    Eigen::MatrixXd matrix;
};

// A contribution beyond the volume cells: springs between nodes or to the
// ground, point masses. Three DOFs per node, node-major like the cells; one
// matrix per term it contributes to (a spring: stiffness only).
struct CouplingElement {
    std::vector<int> nodes;
    std::vector<TermMatrix> terms;
    // The matrix of `term`, or an empty (0 x 0) one.
    const Eigen::MatrixXd& matrix(Term term) const;
};

// A spring k (square, over one set of DOFs) acting on the difference of two
// such sets, first minus second: [k, -k; -k, k] (spring layers between
// facing nodes of core and chuck).
Eigen::MatrixXd spring_between(const Eigen::MatrixXd& k);

// Receives one element matrix of one term with the element's global DOFs
// (-1 for eliminated ones). A run's sink adds into PETSc matrices, a unit
// test's into dense Eigen matrices: the loops below are the same for both.
using TermInsert = std::function<void(Term term, const std::vector<int>& dofs, const Eigen::MatrixXd& matrix)>;

// Loops over the cells for which `take(cell)` is true and inserts their
// stiffness and mass, and each term of `extra_terms` (only Term::gyroscopic:
// element_gyroscopic, for a spinning scene; every cell spins, for the cells
// are the roll and the chuck bodies and shafts, while the bearings, frames
// and spring layers are couplings, which do not). Returns the mass of those
// cells (sum of rho * V), for the "mass equals rho V" check.
double assemble_cells(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                      const std::function<bool(int)>& take, const TermInsert& insert,
                      const std::vector<Term>& extra_terms = {});

// Inserts every term of the couplings for which `take(nodes)` is true, and
// zeros for each term of `pad_to` an element does not have, so that every
// assembled matrix gets the same pattern (PETSc squeezes out preallocated
// entries nobody set, and K - sigma M is formed with SAME_NONZERO_PATTERN).
// Returns their lumped mass (kg).
double assemble_couplings(const std::vector<CouplingElement>& couplings, const DofMap& dofs,
                          const std::function<bool(const std::vector<int>&)>& take, const TermInsert& insert,
                          const std::vector<Term>& pad_to = {});

}  // namespace coremodal
