// The one-sided contact of a chuck that was not expanded
// (effects/support_effects.hpp, OneSidedContact) on the solid's bore faces:
// its integration points, the interpenetration at each, and the coupling
// elements and loads it becomes, once for the static active-set iteration
// and once, linearised about the converged state, for the modes. Plain
// Eigen: the iteration with PETSc is models/solid/gravity_contact.cpp.
//
// Weak form at a point with outward bore normal e_r, relative displacement
// du = u_core - u_chuck (shape functions N of the bore face, the facing body
// node of each bore node) and interpenetration d = -c - e_r . du:
//     energy  integral of Phi(d) dA,  Phi' = p(d) >= 0 (compression only),
// so the tangent is p'(d) e_r e_r^T on [N, -N] and the force on the core
// +p e_r N (the chuck pushes the bore outwards), -p e_r N on the chuck.
#pragma once

#include "assembly/cell_loop.hpp"
#include "effects/support_effects.hpp"

#include <Eigen/Dense>

#include <functional>
#include <vector>

namespace coremodal {

struct ContactPoint {
    Eigen::VectorXd N;       // the bore face's shape values
    Eigen::Vector3d x;       // m, on the bore
    double area_weight = 0;  // m^2
    Eigen::Vector3d normal() const { return Eigen::Vector3d(x[0], x[1], 0).normalized(); }  // e_r
};

// A bore face on a one-sided chuck's body and the body nodes facing it.
struct ContactFace {
    int chuck = 0;                 // index into SupportEffects::chucks
    std::vector<int> core_nodes;   // the face's nodes, gmsh order
    std::vector<int> chuck_nodes;  // the facing body node of each
    std::vector<ContactPoint> points;
};

// The state of one point: interpenetration d (m, > 0 closed), pressure p (Pa).
struct ContactPointState {
    double d = 0;
    double p = 0;
    bool closed() const { return d > 0; }
};

// Nodal displacement (m) of a mesh node; zero for an eliminated node.
using NodeDisplacement = std::function<Eigen::Vector3d(int node)>;

// d = -c - e_r . (u_core - u_chuck) at point q of face f.
double interpenetration(const ContactFace& f, const ContactPoint& q, double clearance, const NodeDisplacement& u);

// The face's coupling element over (core nodes, chuck nodes): the sum over
// its points of area_weight N N^T (x) D(q) on the relative displacement;
// D(q) = 0 leaves a structural zero (the static placeholders).
CouplingElement contact_coupling(const ContactFace& f, const std::function<Eigen::Matrix3d(size_t q)>& D);

// The face's load (3 per node: core nodes, then chuck nodes) of a traction
// t(q) e_r pushing the bore outwards (N/m^2): + on the core, - on the chuck.
Eigen::VectorXd contact_load(const ContactFace& f, const std::function<double(size_t q)>& t);

// The modes' couplings: at every closed point the spring layer at the
// tangent stiffness of its static pressure (OneSidedContact::linearised),
// nothing at open points. `state` runs face-major over the points.
std::vector<CouplingElement> linearised_contact(const std::vector<ContactFace>& faces,
                                                const std::vector<ContactPointState>& state,
                                                const SupportEffects& effects);

}  // namespace coremodal
