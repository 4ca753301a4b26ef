// The static state a one-sided contact's modes are linearised about
// (effects/support_effects.hpp: OneSidedContact, GravityPreload): the solid
// under its weight, along -y, resting on chucks that were not expanded.
//
//   (K + K_c(u)) u = F_g + f_c(u),   F_g = M a,  a = -g e_y at every free node
//
// with the contact's springs and loads (assembly/one_sided_contact.hpp) from
// a Newton linearisation of p(d) at every closed point, nothing at open
// ones. Which points are closed is found by the active-set iteration of
// models/contact_active_set (shared with the coupled harmonics); each of
// its Newton steps here is a solve with a direct Cholesky factor (PETSc
// KSP, the eigensolver's factor package). The points run face-major over
// ChuckSupports::contact_faces. docs/theory/chucks.md, "A chuck that was not expanded".
#pragma once

#include "assembly/chuck_supports.hpp"
#include "assembly/operator_set.hpp"
#include "models/contact_active_set.hpp"
#include "models/model_level.hpp"

#include <string>
#include <vector>

namespace coremodal {

// Collective. Throws SolveError when the Cholesky factor fails or the
// active set does not settle within the iteration limit.
GravityContact solve_gravity_contact(const OperatorSet& base, const DofMap& dofs, const ChuckSupports& supports,
                                     const SupportEffects& effects, const Printer& say);

// Adds the couplings' stiffness into an assembled matrix whose pattern
// already holds them (the ChuckSupports placeholders). Collective.
void add_couplings_to(Mat K, const std::vector<CouplingElement>& couplings, const DofMap& dofs);

}  // namespace coremodal
