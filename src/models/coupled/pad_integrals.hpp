// The theta integrals that couple circumferential harmonics through an
// attachment that acts over arcs of the bore (docs/theory/coupled.md, "Coupled
// harmonics"). A spring layer of stiffness k chi(theta), chi = 1 on the
// arcs and 0 between, stores per unit section length
//     1/2 sum_c k_c int chi(theta) du_c(theta)^2 dtheta  (c = r, theta, z)
// and with du_c = sum over (n, family) of a_c t_c(n, family; theta) each
// pair of harmonics meets through int chi t_c(a) t_c(b) dtheta, computed
// here in closed form from the arcs (exact for every pair, no quadrature).
//
// The trig factor of component c (element/harmonic_element.hpp):
//   family cos, n >= 1: u_r, u_z: cos n theta;  u_theta: -sin n theta
//   family sin, n >= 1: u_r, u_z: sin n theta;  u_theta:  cos n theta
//   n = 0 (one family, "cos"): u_r, u_z: 1;     u_theta: -1
// Plain C++: no Eigen, PETSc or MPI.
#pragma once

#include "effects/chuck_placement.hpp"

#include <vector>

namespace coremodal {

enum class Family { cos, sin };

// One harmonic's share of the field: wave number n and family (n = 0: cos only).
struct HarmonicFamily {
    int n = 0;
    Family family = Family::cos;
    bool operator==(const HarmonicFamily& o) const { return n == o.n && family == o.family; }
};

// int over the arcs of cos(p theta) and sin(p theta), p any integer.
double arcs_cos_integral(const std::vector<Arc>& arcs, int p);
double arcs_sin_integral(const std::vector<Arc>& arcs, int p);

// t_c(h; theta): the trig factor above, at one angle.
double trig_factor(HarmonicFamily h, int component, double theta);

// int over the arcs of t_c(a; theta) t_c(b; theta) dtheta for component c
// (0: r, 1: theta, 2: z).
double pad_integral(const std::vector<Arc>& arcs, HarmonicFamily a, HarmonicFamily b, int component);

// Below this fraction of 2 pi an integral is round-off of one that vanishes
// exactly (e.g. int cos p theta over three pads 120 deg apart, p not a
// multiple of 3: 1e-16); it is dropped so the coupling keeps its sparsity.
inline constexpr double kVanishingIntegral = 1e-12;

}  // namespace coremodal
