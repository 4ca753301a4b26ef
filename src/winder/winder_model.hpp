// The two-drum winder at one roll diameter as a beam network (docs/how-to/winder.md).
//
// Geometry (a cross-section, looking along the drums): x horizontal from the
// front drum towards the rear one, y up, z along the drums. The drum centres
// are at x = -s/2 and +s/2, y = 0, s = d1 + gap; the rolls' centres at x = 0,
// y = h, resting on both drums; the rider on top of the rolls. Each drum nip
// acts along the line joining the centres, at the angle alpha from the
// vertical with sin(alpha) = s / (d + d1): n_front = (sin a, cos a),
// n_rear = (-sin a, cos a); the rider nip acts vertically. As the rolls grow,
// alpha falls (the nips turn towards the vertical).
//
// Bodies: two drums (Timoshenko tubes on a bearing spring at each end),
// the rider (a Timoshenko tube on a spring at each end) and N rolls, each a
// rigid body (default) or a Timoshenko beam of core and paper. Nips are
// distributed springs k_nip n n^T per unit length over each roll's width
// (BeamNetwork couplings), k_nip from Jorkama's formula (nip.hpp) at the line
// load of the roll's equilibrium. Only bending motion is modelled (ux, uy and
// the section rotations rx, ry): nips push radially, so axial and torsional
// motion never couple to them. Rotation of the drums and rolls (gyroscopic
// terms) is left out.
//
// A rigid roll is one Timoshenko element (its mass and rotary inertia exact
// for rigid motion) whose node motions are tied to four rigid-body DOFs
// (ux0, uy0, theta_x, theta_y at its centre) by a transformation T:
// K_reduced = T^T K T. Constraints by transformation, never by penalty
// numbers (DESIGN.md).
#pragma once

#include "beam/beam_network.hpp"
#include "winder/nip.hpp"
#include "winder/winder_scene.hpp"

#include <Eigen/Sparse>

#include <array>
#include <string>
#include <vector>

namespace coremodal {

constexpr double kGravity = 9.81;  // m/s^2, for the rolls' weight on the nips

// Where the rolls lie at roll diameter d.
struct WinderGeometry {
    double roll_diameter = 0;  // d, m
    double drum_spacing = 0;   // s, m between the drum centres
    double nip_angle = 0;      // alpha, rad from the vertical
    double roll_height = 0;    // h, m of the roll centre above the drum centres
};
WinderGeometry winder_geometry(const WinderScene& scene, double roll_diameter);

// Everything of the scene that changes with the roll diameter.
struct WinderState {
    WinderGeometry geometry;
    double roll_mass_per_width = 0;  // kg/m, core and paper
    double drum_line_load = 0;       // N/m on each drum nip
    double rider_line_load = 0;      // N/m on each rider nip
    Nip drum_nip, rider_nip;
};
// Throws InputError (naming the file) when the nip formula does not hold.
WinderState winder_state(const WinderScene& scene, double roll_diameter);

enum class BodyKind { drum, roll, rider };
constexpr int kBodyKinds = 3;
const char* body_kind_name(BodyKind k);  // "drum", "roll", "rider"

struct WinderBody {
    std::string name;  // "front drum", "rear drum", "rider", "roll 1", ...
    BodyKind kind;
    int beam = 0;      // index in the network
    double z_start = 0, z_end = 0;  // m
};

struct WinderModel {
    WinderState state;
    BeamNetwork network;
    std::vector<WinderBody> bodies;  // front drum, rear drum, rider, rolls
    // The reduced problem K x = lambda M x on the bending DOFs (rigid rolls
    // replaced by their rigid-body DOFs), and the nips' share of K.
    Eigen::SparseMatrix<double> K, M, K_nips;
    // Network bending DOFs (6 * node + beam_dof) = T * reduced DOFs.
    Eigen::SparseMatrix<double> T;
    std::vector<int> network_dofs;  // the network DOF of each row of T
    std::vector<int> body_of;       // the body of each reduced DOF
    std::array<int, 2> drum_centre_node{};  // front, rear: the node at mid-span

    int n_dofs() const { return static_cast<int>(K.rows()); }
    // The reduced DOF of a network DOF that is not inside a rigid roll.
    int reduced_dof(int node, int dof) const;
};

WinderModel build_winder_model(const WinderScene& scene, double roll_diameter);

// The drum nip's direction (unit, in x-y) from the drum's centre to the roll's.
std::array<double, 2> nip_direction(const WinderGeometry& g, DrumSide drum);

// Element ends from a to b with a node on every break point inside and about
// `n_target` elements in all (at least one between neighbouring breaks).
std::vector<double> element_ends(double a, double b, std::vector<double> breaks, int n_target);

}  // namespace coremodal
