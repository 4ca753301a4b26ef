// From distributed eigenvectors to node displacements and effective masses.
#pragma once

#include "assembly/dof_map.hpp"
#include "common/petsc_handle.hpp"
#include "mesh/mesh.hpp"
#include "modes/mode_set.hpp"

#include <array>
#include <vector>

namespace coremodal {

// x gathered to rank 0 as plain values (empty on other ranks). Collective.
std::vector<double> gather_to_root(Vec x);
// x on every rank (the static contact's displacements). Collective.
std::vector<double> gather_to_all(Vec x);

// Gathers x to rank 0 and expands it to every mesh node (n_nodes x 3,
// eliminated nodes zero). Other ranks get an empty vector. Collective.
std::vector<double> gather_node_displacements(Vec x, const Mesh& mesh, const DofMap& dofs);

// Effective modal mass of an M-normalised mode: Gamma_d^2 with
// Gamma_d = x^T M r_d, r_d the rigid-body motion in direction d (translation
// x, y, z; rotation about the z axis). Summed over all modes of a free–free
// model they give the total mass (and polar moment of inertia).
class EffectiveMassCalculator {
public:
    EffectiveMassCalculator(Mat M, const Mesh& mesh, const DofMap& dofs);
    EffectiveMass operator()(Vec x) const;

private:
    std::array<PetscVector, 4> M_r_;
};

}  // namespace coremodal
