// The static state of a one-sided contact at the coupled-harmonic level
// (docs/theory/coupled.md, "The one-sided contact"): the roll under its weight,
// along -y, resting on chucks that were not expanded, by the active-set
// Newton iteration of models/contact_active_set (the solid's, shared), each
// step a Cholesky solve of the coupled harmonics with the contact's
// linearised springs at the points of models/coupled/contact_layer.
//
// The weight is the consistent load M a, a = -g e_y: the y translation,
// which lives in block (1, sin) alone (U = V = 1 there; the mass never
// couples blocks). Gravity and an arc symmetric about the vertical are even
// under the mirror x -> -x (theta -> pi - theta). Under it cos n theta picks
// up (-1)^n and sin n theta (-1)^(n+1), and u_theta changes sign with the
// mirror, so the cos family of n is even for n even and the sin family for
// n odd; n = 0's (U, W) are even and its torsion V odd. The static state
// lies in the even blocks (0), (2, cos), (1, sin), (3, sin), (4, cos), ...
// and is solved there only: half the blocks, the same answer (the odd
// blocks carry no load and, with a symmetric active set, no coupling to
// the even ones; n = 0's V is held by the static tangential spring).
#pragma once

#include "models/coupled/coupled_system.hpp"
#include "models/part_materials.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The static state is solved once, with the harmonics n = 0 ... this, and
// the modes at every N are linearised about it (so that the modes' spaces
// stay nested and their frequencies fall monotonically with N).
// docs/theory/coupled.md measures the state's convergence in this N.
inline constexpr int kContactStaticHarmonics = 16;

// Whether block h is even under the mirror x -> -x (above).
bool mirror_even(HarmonicFamily h);

struct CoupledContactState {
    GravityContact contact;  // per point of `layer.points` and per chuck
    ContactLayer layer;      // for the modes: diag(k_n(p), k_t(p), k_t(p)) at the closed points, 0 at open ones
};

// Collective. Throws SolveError when the Cholesky factor fails or the active
// set does not settle.
CoupledContactState solve_coupled_contact(const Scene& scene, const SectionMesh& section,
                                          const std::vector<PartMaterial>& materials, int n_max, const Printer& say);

}  // namespace coremodal
