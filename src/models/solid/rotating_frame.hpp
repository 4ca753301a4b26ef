// A spinning solid in co-rotating coordinates (docs/theory/rotation-solid.md, "Scenes
// that are not bodies of revolution"). Segments, a user mesh: the spinning
// parts carry their asymmetry round with them, so in the stationary frame
// the coefficients are periodic in time; seen from axes turning with the
// roll they are constant, as long as everything that does not spin looks
// the same from every angle (clamps, which turn with the core; bearing
// springs equal in x and y; frame masses; no gravity, no one-sided contact):
//
//   M q'' + Omega G_c q' + (K + Omega^2 (K_sigma1 - M_P)) q = 0,
//   G_c = 2 int rho N^T J N dV,  M_P = int rho N^T P N dV,
//
// J = e_z x (skew: J u = (-u_y, u_x, 0)), P = diag(1, 1, 0): the Coriolis
// force and the spin softening of the co-rotating equations
// (effects/rotation.hpp), over every mass, the non-spinning isotropic parts'
// too (for them a pure change of coordinates); K_sigma1 on the spinning
// cells (models/solid/centrifugal_prestress). Every mass matrix of the
// solid is m (x) I3 per node pair (consistent cells, lumped frames), so
// G_c = 2 M T_J and M_P = M T_P with T_J, T_P the node-wise 3x3 blocks.
//
// Its frequencies are the rotating frame's. A mode whose shape on the roll's
// surface is dominated by the signed circumferential harmonic e^{i k theta}
// (k < 0: a wave travelling with the spin in the rotating frame) is seen
// from the stationary frame at f_stat = |f - k f_rot|, travelling forward
// when -k (f - k f_rot) > 0: exact for a body of revolution (one harmonic
// per mode), the dominant harmonic's share saying how nearly so otherwise.
#pragma once

#include "assembly/chuck_supports.hpp"
#include "assembly/operator_set.hpp"
#include "mesh/mesh.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// Why the scene cannot spin in co-rotating coordinates (a one-sided
// contact under gravity), or nothing. Before any work.
std::optional<std::string> why_not_corotating(const Scene& scene);

// Why the meshed supports are not the same from every angle: a coupling to
// the ground or to a frame whose stiffness differs in x and y; or nothing.
std::optional<std::string> anisotropic_support(const ChuckSupports& supports);

// Adds G_c (Term::gyroscopic) and -M_P to Term::centrifugal (created if
// absent) from the set's M.
void add_rotating_frame_terms(OperatorSet& operators, const DofMap& dofs);

// The nodes on the roll's outer surface (the largest radius of `roll_nodes`).
std::vector<int> roll_surface_nodes(const Mesh& mesh, const std::vector<int>& roll_nodes);

// The dominant signed harmonic of a complex node field (re + i im, 3 per
// node) on `surface` nodes, in cylindrical components: k and its share of
// the field's energy over |k| <= max_k.
struct WaveContent {
    int k = 0;
    double share = 1;
};
WaveContent dominant_harmonic(const std::vector<double>& re, const std::vector<double>& im, const Mesh& mesh,
                              const std::vector<int>& surface, int max_k);

}  // namespace coremodal
