// Stiffness K and mass M as distributed PETSc AIJ matrices (block size 3),
// preallocated exactly from the mesh graph. Every rank holds the whole mesh
// (meshes here are at most a few million nodes) and assembles the cells whose
// first free node it owns; off-rank entries travel through PETSc's stash.
#pragma once

#include "assembly/cell_loop.hpp"
#include "common/petsc_handle.hpp"

namespace coremodal {

struct PetscSystem {
    PetscMatrix K, M;
    double model_mass = 0;  // sum of rho V over all cells, kg (all ranks)
};

PetscSystem assemble_petsc(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                           const std::vector<CouplingElement>& couplings = {}, MPI_Comm comm = PETSC_COMM_WORLD);

}  // namespace coremodal
