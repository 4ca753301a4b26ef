// The axisymmetric equivalent of a scene whose chucks press on the bore with
// segmented pads: every segmented element widened to a full band whose
// spring layer's stiffness (normal and tangential, per unit bore area) is
// scaled by the pads' angular coverage c = N_s x segment_angle / 2 pi.
//
// Why it is exact for the n = 1 family (the lateral, tilting one the
// spinning criteria live in): the layer's stiffness between harmonics a and
// b is k_c int chi(theta) t_c(a) t_c(b) dtheta (models/coupled/
// pad_integrals.hpp). For n = 1 the factors are cos theta and sin theta, and
// over N >= 3 equal pads of span alpha centred at theta_k = 2 pi k / N
//     sum_k int_{theta_k - alpha/2}^{theta_k + alpha/2} cos^2 theta dtheta
//       = N alpha / 2 + (sin alpha / 2) sum_k cos 2 theta_k = N alpha / 2
//       = c pi,
// since sum_k cos 2 theta_k = sum_k sin 2 theta_k = 0 unless N divides 2;
// the same for sin^2 theta, and the cross term sum_k int cos sin vanishes.
// The full band gives pi: so the band with k scaled by c stores the pads'
// energy for every n = 1 displacement. It is not exact for N = 1, 2 (the
// sums are N, not 0: the pads are stiffer in one direction than the other)
// and it leaves out the pads' coupling of n = 1 to n = |1 +- j N| (the
// coupled level keeps it; the verdict measures the difference in f1).
#pragma once

#include "scene/scene.hpp"

#include <string>

namespace coremodal {

struct AxisymmetricEquivalent {
    Scene scene;             // no segmented element left; model as the input's
    double coverage = 1.0;   // the pads' angular coverage (the smallest over the chucks)
    std::string assumption;  // what was done, for the run's output
};

// The pads' angular coverage of one segmented element, N_s segment_angle / 2 pi.
double pad_coverage(const ExpandingElement& e);

// Throws InputError naming the chuck and what is expected for a chuck whose
// pads the equivalent cannot carry: fewer than 3 pads, segmented and full
// elements (or pads of different counts or spans) on one chuck (its spring
// layer is one stiffness), a bonded interface or a chuck not expanded.
AxisymmetricEquivalent axisymmetric_equivalent(const Scene& scene);

}  // namespace coremodal
