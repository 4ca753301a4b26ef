// The one-sided contact of a chuck not expanded (effects/support_effects.hpp,
// OneSidedContact) at the coupled-harmonic level (docs/theory/coupled.md, "The
// one-sided contact"). The contact's pressure varies with theta over an arc
// the static state decides, so it is integrated by quadrature: on every
// interface edge of a one-sided chuck, Gauss points along z times
// kContactPointsAround uniform angles. At a point, the relative radial
// displacement of core minus chuck is
//     du_r(theta_q, z_g) = sum over blocks h of t_r(h; theta_q) sum_a N_a(z_g) (U_core - U_chuck)_{h,a}
// (t_c the trig factors of models/coupled/pad_integrals.hpp), the
// interpenetration d = -c - du_r. A spring layer diag(k_r, k_theta, k_z)
// per unit area at the points couples blocks a and b through
//     sum_q w_q k_c(q) t_c(a; theta_q) t_c(b; theta_q) N_i N_j     (c = r, theta, z),
// the pads' coupling with the theta integral replaced by the quadrature.
// The uniform rule with P points integrates trig products exactly up to
// degree P - 1, so for a smooth k(theta) it is the integral for every
// pair with n + m < 128; where k jumps (the arc's ends), the sum is what
// the solid's points integrate too. Plain Eigen: the static solve is
// models/coupled/contact_static.cpp.
#pragma once

#include "geometry/section_mesh.hpp"
#include "models/contact_active_set.hpp"
#include "models/coupled/pad_integrals.hpp"
#include "scene/scene.hpp"

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace coremodal {

// 128 angles around: the solid's default 32 elements around times its 4
// Gauss points per face edge (assembly/chuck_supports.cpp, kSpringLayerGauss),
// so that both levels see an arc of contact in the same steps.
inline constexpr int kContactPointsAround = 128;
// Gauss points along z per interface edge: the solid's 4 per face edge
// (kSpringLayerGauss); exact for the quadratic edge's N_i N_j times a
// pressure that varies linearly along the edge.
inline constexpr int kContactGaussAlong = 4;

// One contact point: on interface edge `edge` of its chuck (index into the
// section's "interface_<chuck>_core" and "_chuck" edge groups, which face
// each other), at the edge's Gauss point with shape values N, angle theta.
struct HarmonicContactPoint {
    BorePoint bore;      // chuck, x = (r cos theta, r sin theta, z), area weight r ds w_g 2 pi / P
    int edge = 0;
    Eigen::Vector3d N;   // shape values of the edge's nodes (end, end, middle)
    int around = 0;      // index of theta among the kContactPointsAround angles
    double theta = 0;    // rad
};

// Every candidate point of every one-sided chuck, ordered by chuck, edge,
// Gauss point and angle. Empty for a scene without a one-sided contact.
std::vector<HarmonicContactPoint> contact_points(const Scene& scene, const SectionMesh& mesh);

// The contact as a spring layer on its points: k per unit area on (r,
// theta, z) at each (zero where the point is open).
struct ContactLayer {
    std::vector<HarmonicContactPoint> points;
    std::vector<Eigen::Vector3d> stiffness;
    // sum over the points at angle index q of w k_c: what the coupling of
    // two blocks integrates against (contact_integral).
    std::vector<Eigen::Vector3d> weight_around;
    void set_stiffness(std::vector<Eigen::Vector3d> k);
};

// sum_q weight_around_c(q) t_c(a; theta_q) t_c(b; theta_q) for component c.
double contact_integral(const ContactLayer& layer, HarmonicFamily a, HarmonicFamily b, int component);

// Whether the layer couples blocks a and b: some component's integral
// above round-off (1e-12 of the layer's total) of one that vanishes by symmetry.
bool contact_couples(const ContactLayer& layer, HarmonicFamily a, HarmonicFamily b);
// The same for component c alone.
bool contact_couples(const ContactLayer& layer, HarmonicFamily a, HarmonicFamily b, int component);

// The layer between blocks a and b on one edge pair, per pair of node
// values: 9 x 9, node-major (U, V, W), on the relative displacement core
// minus chuck (spring_between makes the 18 x 18). `first`, `last`: the
// edge's points in layer.points.
Eigen::Matrix<double, 9, 9> contact_edge_matrix(const ContactLayer& layer, size_t first, size_t last,
                                                HarmonicFamily a, HarmonicFamily b);

}  // namespace coremodal
