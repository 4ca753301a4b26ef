// The solid level's operators as distributed PETSc AIJ matrices (block size 3),
// preallocated exactly from the mesh graph. Every rank holds the whole mesh
// (meshes here are at most a few million nodes) and assembles the cells whose
// first free node it owns; off-rank entries travel through PETSc's stash.
#pragma once

#include "assembly/cell_loop.hpp"
#include "assembly/operator_set.hpp"

namespace coremodal {

// One matrix per term the cells and couplings contribute (stiffness and mass
// always; the cells' `extra_terms`, assemble_cells: the gyroscopic term of a
// spinning scene), all with the same preallocated pattern.
OperatorSet assemble_petsc(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                           const std::vector<CouplingElement>& couplings = {}, MPI_Comm comm = PETSC_COMM_WORLD,
                           const std::vector<Term>& extra_terms = {});

}  // namespace coremodal
