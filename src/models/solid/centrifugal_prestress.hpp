// The centrifugal prestress of a spinning solid (effects/rotation.hpp,
// docs/theory/rotation-solid.md "The solid level"): per unit Omega^2,
//
//   1. the static solve K u1 = f1, f1 = int rho N (x, y, 0) dV over every
//      cell (every cell spins; springs, frames and bearings do not), with
//      the scene's supports (K of the operator set: clamps eliminated,
//      bearings and spring layers in it);
//   2. sigma1 = C eps(u1) at the integration points;
//   3. Term::centrifugal, per cell K_sigma1 - M_L (the stationary frame's
//      K_Omega) or K_sigma1 alone (the rotating frame, which adds its own
//      spin softening over every mass: models/solid/rotating_frame).
//
// A free scene's K is singular: rigid motions it leaves free are found by
// K r ~ 0 (translations, rotations) and one DOF is pinned per free motion.
// The load does no work on any of them (no z component; radial, so none on
// a rotation about z; and on a translation or tilt only the mass's
// first moments, zero for a body centred on its axis), so the pins carry
// no reaction and u1 is exact up to a rigid motion, which has no stress.
#pragma once

#include "assembly/centrifugal_cells.hpp"
#include "assembly/operator_set.hpp"
#include "element/centrifugal_element.hpp"

#include <string>
#include <vector>

namespace coremodal {

struct CentrifugalState {
    std::vector<double> node_displacement;  // u1, 3 per mesh node (m per (rad/s)^2), zero where eliminated
    std::vector<std::string> pinned;        // the rigid motions K left free, one DOF pinned for each
    double load_work_on_pinned = 0;         // max |r^T f1| / (|r| |f1|) over them: the pins' reaction, ~0
};

// Steps 1 above. SolveError when the Cholesky factor fails. One process.
CentrifugalState solve_centrifugal_state(const OperatorSet& operators, const Mesh& mesh,
                                         const std::vector<PartMaterial>& materials, const DofMap& dofs);

// Steps 2-3: adds Term::centrifugal to the set, with K's pattern.
void add_centrifugal_term(OperatorSet& operators, const Mesh& mesh, const std::vector<PartMaterial>& materials,
                          const DofMap& dofs, const CentrifugalState& state, CentrifugalPart part);

// The stresses (Cartesian, Pa per (rad/s)^2) at every integration point of
// every cell, for tests and reports.
std::vector<PointStress> centrifugal_stresses(const Mesh& mesh, const std::vector<PartMaterial>& materials,
                                              const CentrifugalState& state);

}  // namespace coremodal
