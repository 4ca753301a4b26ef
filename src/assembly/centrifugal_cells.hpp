// The cell loops of the centrifugal term (element/centrifugal_element.hpp,
// effects/rotation.hpp), independent of the matrix format like
// assemble_cells: every cell spins (core, rest paper, chuck bodies and
// shafts), the couplings (spring layers, bearings, frames) do not, so only
// cells contribute. A unit test fills dense matrices; a spinning run PETSc's.
#pragma once

#include "assembly/cell_loop.hpp"

#include <functional>
#include <vector>

namespace coremodal {

// Receives one cell's vector with its global dofs (-1 for eliminated ones).
using VectorInsert = std::function<void(const std::vector<int>& dofs, const Eigen::VectorXd& vector)>;

// The displacement of a mesh node (3 components, m per unit Omega^2);
// eliminated nodes give zero.
using NodeField = std::function<Eigen::Vector3d(int node)>;

// The spin frame whose Omega^2 terms are assembled (effects/rotation.hpp,
// docs/theory/rotation.md): the stationary frame's K_Omega = K_sigma1 - M_L (bodies
// of revolution), or K_sigma1 alone, to which the rotating frame adds its
// spin softening -M_P over every mass (models/solid/rotating_frame).
enum class CentrifugalPart { stationary_frame, stress_stiffness_only };

// f1 of the cells `take` selects, per unit Omega^2.
void assemble_centrifugal_load(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                               const std::function<bool(int)>& take, const VectorInsert& insert);

// The centrifugal term of the cells `take` selects about the static
// displacement u1 (per unit Omega^2), inserted as Term::centrifugal.
void assemble_centrifugal_cells(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                                const std::function<bool(int)>& take, const NodeField& u1, CentrifugalPart part,
                                const TermInsert& insert);

}  // namespace coremodal
