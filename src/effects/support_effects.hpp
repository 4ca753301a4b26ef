// How a scene holds its roll, stated once for every model level: rigid
// clamps, the chuck's contact (a spring layer or bonded ties) over its
// expanding elements, and the stand (rigid bearing, bearing springs, frame
// mass). Each effect is a small struct computed from the Scene, with its
// name in the summary's `effects` list and the terms (element/term.hpp) it
// adds. The levels only translate it into their DOFs:
//
//   effect              solid (assembly/chuck_supports)   harmonic (assembly/harmonic_system)   beam (beam/beam_model)
//   rigid_clamps        clamp nodes eliminated            clamp nodes held                      clamp-zone nodes held
//   elastic_chucks      chuck body + shaft cells           chuck section cells                   a steel beam per chuck
//     bonded tie        bore node takes chuck node's DOFs  bore components tied                  body shares core nodes
//   contact_compliance  coupling per bore face             ring spring per interface edge        spring layer per length
//   one_sided_contact   static active set under gravity,   refused (not axisymmetric)            refused
//     + gravity_preload then a coupling per bore face on
//                       the closed points
//   rigid bearing       shaft end face eliminated          shaft end edges held                  shaft end node held
//   bearing_springs     springs spread over the end face   ring springs over the end edges       radial + tilting springs
//   frame_mass          frame node, 3 translations         one DOF in n = 0 and n = 1            frame node, 2 translations
//
// docs/theory/chucks.md gives the formulas.
#pragma once

#include "effects/chuck_placement.hpp"
#include "element/term.hpp"
#include "scene/chuck_contact.hpp"
#include "scene/scene.hpp"

#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// A rigid clamp on the bore over a zone: its nodes' DOFs are eliminated
// (held), never penalised. Adds no term.
struct RigidClamp {
    static constexpr const char* kName = "rigid_clamps";
    std::string name;  // "left" or "right": the mesh groups are "clamp_<name>"
    ZRange zone;       // m, from the left core end
};

// The contact of an expanding element with the bore as a distributed spring
// layer on the relative displacement du = u_core - u_chuck of facing points:
// stiffness per unit bore area k_n along the radius and k_t in the tangent
// plane (from the expansion pressure and the contact law,
// scene/chuck_contact.hpp, or given). Energy per area 1/2 du^T D du,
//     D = k_t I + (k_n - k_t) e_r e_r^T.
struct SpringLayer {
    static constexpr const char* kName = "contact_compliance";
    static constexpr Term kTerm = Term::stiffness;
    double normal = 0;      // k_n, Pa/m
    double tangential = 0;  // k_t, Pa/m

    // D in Cartesian (x, y, z) at the bore angle theta.
    Eigen::Matrix3d per_area(double theta) const;
    // D on cylindrical (r, theta, z) components: diag(k_n, k_t, k_t).
    Eigen::Vector3d per_area_cylindrical() const { return {normal, tangential, tangential}; }
    // Force per unit rigid sideways translation of the core against the
    // chuck over one expanding element, N/m: (k_n + k_t)/2 times the pressed
    // area, averaged around (pi R w (k_n + k_t) for a full band).
    double sideways_stiffness(const ExpandingElement& e, double bore_radius) const;
    // The same along the axis: k_t times the pressed area.
    double axial_stiffness(const ExpandingElement& e, double bore_radius) const;
};

// A chuck that was not expanded (contact = "one-sided", docs/theory/chucks.md): the
// bore rests on the chuck body across the radial clearance where the roll's
// weight closes it, anywhere on the inserted length. Interpenetration of the
// layer at a bore point with outward normal e_r,
//     d = -clearance - e_r . (u_core - u_chuck),   closed while d > 0,
// carries p(d) = K1 (exp(d/u0) - 1) (scene/chuck_contact.hpp). The modes are
// linearised about the static state: where closed, the spring layer at the
// tangent stiffness k_n(p) and Mindlin's k_t = ratio k_n(p) (stuck); where
// open, nothing.
struct OneSidedContact {
    static constexpr const char* kName = "one_sided_contact";
    static constexpr Term kTerm = Term::stiffness;
    double clearance = 0;         // m, radial, bore minus body
    StackContact law;             // k_n0 (Pa/m) and K1 (Pa)
    double tangential_ratio = 0;  // k_t / k_n

    // The spring layer of a closed point at contact pressure p (Pa).
    SpringLayer linearised(double p) const {
        const double k = law.stiffness(p);
        return {k, tangential_ratio * k};
    }
};

// The scene's weight, along -y, as the static load whose state the modes of
// a one-sided contact are linearised about: the consistent body force
// M g (every part, lumped frame masses too). Only with a one-sided contact:
// an expanded or bonded chuck's modes do not depend on it (no geometric
// stiffness from gravity is added: the static stresses are small).
struct GravityPreload {
    static constexpr const char* kName = "gravity_preload";
    double g = kStandardGravity;  // m/s^2, along -y
};

// The area of the bore an expanding element presses on, m^2.
double contact_area(const ExpandingElement& e, double bore_radius);

// An elastic bearing: the shaft end held by a radial spring (N/m, each of x
// and y) and a tilting spring (N m/rad, about x and y). Spread over the
// shaft end face (solid, harmonic) as springs per unit face area
//     c_r = k_radial / A  in x and y,   c_z = k_tilt / I  along z
// (A and I the face's area and second moment about a diameter), so that the
// face as a whole translates against k_radial and tilts against k_tilt.
struct BearingSprings {
    static constexpr const char* kName = "bearing_springs";
    static constexpr Term kTerm = Term::stiffness;
    double radial = 0;   // N/m
    double tilting = 0;  // N m/rad

    // (c_r, c_r, c_z) on (x, y, z), or on (r, theta, z): the same numbers.
    Eigen::Vector3d per_face_area(double area, double second_moment) const {
        return {radial / area, radial / area, tilting / second_moment};
    }
};

// A lumped frame mass behind an elastic bearing: the bearing springs join the
// shaft end to it, and a frame spring joins it to the ground.
struct FrameMass {
    static constexpr const char* kName = "frame_mass";
    double mass = 0;       // kg
    double stiffness = 0;  // N/m, frame to ground
    double z = 0;          // m, the bearing centre on the axis
};

// One chuck's effects. The chuck body and shaft are parts of the model (with
// the chuck's material), named "elastic_chucks"; over the expanding elements
// the core is held either by ties (bonded) or by a spring layer.
struct ChuckEffects {
    static constexpr const char* kName = "elastic_chucks";
    ChuckPlacement placement;
    bool bonded = false;
    std::optional<SpringLayer> spring_layer;        // interface = "spring", contact = "uniform"
    std::optional<OneSidedContact> one_sided;       // interface = "spring", contact = "one-sided"
    std::optional<BearingSprings> bearing_springs;  // absent: a rigid bearing
    std::optional<FrameMass> frame;                 // only with bearing springs
};

struct SupportEffects {
    std::vector<RigidClamp> clamps;    // left then right
    std::vector<ChuckEffects> chucks;  // left then right, as Scene::supports.chucks
    std::optional<GravityPreload> gravity;  // with any one-sided contact
};

SupportEffects support_effects(const Scene& scene);

// The names of the effects a scene simulates, in the summary's vocabulary:
// "core" always, "rest_paper" when there is one, then each support effect
// applied (rigid_clamps, elastic_chucks, contact_compliance,
// one_sided_contact, gravity_preload, bearing_springs, frame_mass). A free-free scene adds nothing: free is the absence of supports.
std::vector<std::string> effect_names(const Scene& scene, const SupportEffects& effects);

}  // namespace coremodal
