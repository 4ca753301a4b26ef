// The harmonic level's modes of the same scene at the solid mesh's nodes:
// block Lanczos's first block on a body of revolution (issue 39). The
// harmonic level solves the section exactly in theta in under a second; its
// modes are near the solid's, so the solid's Krylov space holds the wanted
// pairs after fewer passes over the factor. What is accepted, and the
// count, are the solver's as for a random start (eigensolve/block_lanczos.hpp).
#pragma once

#include "assembly/dof_map.hpp"
#include "common/petsc_handle.hpp"
#include "geometry/section_mesh.hpp"
#include "modes/mode_set.hpp"

#include <petscmat.h>

#include <memory>
#include <vector>

namespace coremodal {

// Each of `modes` (shapes on `revolved`, node-major x, y, z; the axis is z)
// at every node of `solid`: the nearest section node in (r, z), its field
// interpolated linearly in theta between the revolved planes in cylindrical
// components. One vector per mode in K's layout (the free DOFs of `dofs`).
// Empty when the shapes are not here (several processes: rank 0 holds them).
std::vector<PetscVector> harmonic_modes_on_solid(const RevolvedMesh& revolved, const std::vector<Mode>& modes,
                                                 const Mesh& solid, const DofMap& dofs, Mat K);

}  // namespace coremodal
