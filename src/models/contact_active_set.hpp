// The active-set Newton iteration that finds where a one-sided contact
// (effects/support_effects.hpp: OneSidedContact, GravityPreload) closes under
// the roll's weight, generic over its contact points: the 3D solid's bore
// face points (models/solid/gravity_contact.cpp) and the coupled harmonics'
// Gauss x theta points (models/coupled/contact_layer.cpp) run the same loop.
// What a level supplies is one Newton step: solve
//
//   (K + K_c) u = F_g + f_c,   K_c = sum over active points of w k(p_i) D_static,
//   f_c = sum over active points of w (p_i - k(p_i) (d_i + c)) e_r  (on the core, minus on the chuck)
//
// with the iterate's linearisation and return the interpenetration
// d = -c - e_r . (u_core - u_chuck) at every point. The loop starts with the
// bore's top closed, closes every point whose d came out positive and opens
// every other, damping a step that would close a point too far, until the
// set repeats and the Newton step is below 1e-8 of the layer's scale u0.
// docs/theory/chucks.md, "A chuck that was not expanded".
#pragma once

#include "assembly/one_sided_contact.hpp"  // ContactPointState
#include "effects/support_effects.hpp"
#include "models/model_level.hpp"

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace coremodal {

// In the static solve the contact is frictionless: a symmetric roll's
// weight is carried by normal pressure, and friction would only resist the
// slip while the clearance closes. A tangential spring of this fraction of
// k_n at closed points removes the two motions nothing else holds (the roll
// turning about its axis and sliding along it, which the weight does not
// load); it carries about 1e-6 of the load.
inline constexpr double kStaticTangentialFraction = 1e-6;

// One contact point on the bore, as the iteration and its summary see it.
struct BorePoint {
    int chuck = 0;           // index into SupportEffects::chucks
    Eigen::Vector3d x;       // m, on the bore
    double area_weight = 0;  // m^2
    Eigen::Vector3d normal() const { return Eigen::Vector3d(x[0], x[1], 0).normalized(); }  // e_r
};

// The linearisation of one iteration: which points carry springs, and the
// (d, p) each is linearised about.
struct ContactIterate {
    std::vector<char> active;
    std::vector<double> d, p;
};

// Point i's static spring, per unit area in (r, theta, z): k(p_i) on the
// normal and kStaticTangentialFraction k(p_i) on the two tangents; zero
// where the iterate has the point open.
Eigen::Vector3d static_contact_stiffness(const OneSidedContact& contact, const ContactIterate& it, size_t i);

// Point i's constant traction of the linearised pressure, p_i - k(p_i) (d_i + c)
// (N/m^2, pushing the bore outwards); zero where open.
double static_contact_traction(const OneSidedContact& contact, const ContactIterate& it, size_t i);

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
    std::vector<ContactPointState> state;  // one per point, in the order the level gave them
    std::vector<ChuckContactState> chucks;
    int iterations = 0;
    std::vector<int> closed_history;  // closed points after each iteration
};

// The interpenetration at every point after solving with the iterate's linearisation.
using ContactNewtonStep = std::function<std::vector<double>(const ContactIterate&)>;

// Throws SolveError when every point opens or the active set does not
// settle within the iteration limit (and passes on the step's own errors).
GravityContact solve_active_set(const std::vector<BorePoint>& points, const SupportEffects& effects,
                                const ContactNewtonStep& step, const Printer& say);

// One line per chuck for the run's assumptions and console.
std::vector<std::string> contact_state_lines(const GravityContact& contact, double roll_weight_n);

}  // namespace coremodal
