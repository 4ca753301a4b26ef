// The static state a one-sided contact's modes are linearised about
// (effects/support_effects.hpp: OneSidedContact, GravityPreload): the solid
// under its weight, along -y, resting on chucks that were not expanded.
//
//   (K + K_c(u)) u = F_g + f_c(u),   F_g = M a,  a = -g e_y at every free node
//
// with the contact's springs and loads (assembly/one_sided_contact.hpp) from
// a Newton linearisation of p(d) at every closed point, nothing at open
// ones. Which points are closed is found by an active-set iteration: start
// with the bore's top closed, solve with a direct Cholesky factor
// (PETSc KSP, the eigensolver's factor package), close every point whose
// interpenetration came out positive and open every other, until the set
// repeats and the Newton step is below 1e-8 of the layer's scale u0.
// docs/chucks.md, "A chuck that was not expanded".
#pragma once

#include "assembly/chuck_supports.hpp"
#include "assembly/operator_set.hpp"
#include "models/model_level.hpp"

#include <string>
#include <vector>

namespace coremodal {

// One chuck's closed contact in the static state.
struct ChuckContactState {
    std::string chuck;
    int closed_points = 0, points = 0;
    double arc_deg = 0;                 // angular extent of the closed points, centred near the top
    double z_from_m = 0, z_to_m = 0;    // their axial extent
    double closed_area_m2 = 0;
    double vertical_force_n = 0;        // the contact's upward force on the roll
    double max_pressure_pa = 0;
    // What the linearised contact holds the core by, against the chuck, for
    // rigid motions of the core: a vertical and a horizontal translation,
    // and a tilt in the vertical plane (about x, through the middle of the
    // closed zone): sum of area_weight u^T D u over the closed points.
    double vertical_stiffness_n_per_m = 0, horizontal_stiffness_n_per_m = 0;
    double tilt_stiffness_nm_per_rad = 0;
};

struct GravityContact {
    std::vector<ContactPointState> state;  // face-major over ChuckSupports::contact_faces
    std::vector<ChuckContactState> chucks;
    int iterations = 0;
    std::vector<int> closed_history;  // closed points after each iteration
};

// Collective. Throws SolveError when the Cholesky factor fails or the
// active set does not settle within the iteration limit.
GravityContact solve_gravity_contact(const OperatorSet& base, const DofMap& dofs, const ChuckSupports& supports,
                                     const SupportEffects& effects, const Printer& say);

// Adds the couplings' stiffness into an assembled matrix whose pattern
// already holds them (the ChuckSupports placeholders). Collective.
void add_couplings_to(Mat K, const std::vector<CouplingElement>& couplings, const DofMap& dofs);

// One line per chuck for the run's assumptions and console.
std::vector<std::string> contact_state_lines(const GravityContact& contact, double roll_weight_n);

}  // namespace coremodal
