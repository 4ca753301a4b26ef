// Naming a mode: circumferential wave number n, axial nodes m, and a type.
//
// Method: the nodes are cut into axial stations (bins in z). In each station
// every cylindrical displacement component (u_r, u_theta, u_z) is fitted by
// least squares with a Fourier series in theta up to kMaxWaveNumber. The
// energy of harmonic n, summed over stations and components, gives the family
// shares; the dominant n and component give the type:
//   n = 0: breathing (u_r), torsion (u_theta), axial (u_z);
//   n = 1: bending; n >= 2: ovalling;
//   rigid when lambda is negligible against the first elastic eigenvalue;
//   mixed when no family holds at least kMinDominantShare of the energy.
// A mode whose roll moves as a rigid body (its best rigid-body fit leaves
// less than kRigidMotionDeformationShare of the motion's mean square) is
// not the roll's own vibration, whatever its frequency: on supports it is
// "support" (the roll swinging, bouncing or rocking on compliant chucks,
// bearings or contact arcs; n and m say which: n = 1, m = 0 a sideways or
// vertical translation, n = 1, m = 1 rocking, n = 0 axial or torsional),
// on a free body "rigid" (the nutation and whirl of a spinning free body,
// at a frequency set by its speed).
// m counts the sign changes along z of the dominant harmonic's amplitude,
// projected on its principal circumferential phase (so both members of a
// degenerate pair, arbitrarily rotated, get the same m).
#pragma once

#include "eigensolve/tolerances.hpp"
#include "mesh/mesh.hpp"
#include "modes/mode_set.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace coremodal {

constexpr int kMaxWaveNumber = 8;

// Deformation share below which a mode is a rigid-body motion of the roll.
// An elastic mode of a free body is mass-orthogonal to its rigid motions
// (share near 1); a roll's first bending mode between rigid clamps keeps
// 19 % (pinned, a half sine: 1 - (2/pi)^2 / (1/2)) to 33 % (clamped,
// 1 - cos) of its mean square off the best translation. Five per cent is
// far below both, and above the few per cent a rigid roll's swinging on
// its supports deforms it.
constexpr double kRigidMotionDeformationShare = 0.05;

// Whether the body is held (supports, a web) or free: names rigid-body
// motions at non-zero frequency "support" or "rigid".
enum class BodyHeld { held, free };

// The nodes the classifier looks at: those of the core and rest paper cells
// (a chuck or shaft bends with the roll but is not what the labels describe).
std::vector<int> roll_nodes(const Mesh& mesh);

// Geometric data of the nodes reused for every mode of a mesh.
struct ModeClassifier {
    // Only the nodes in `nodes` (all when empty) are looked at: with chucks,
    // the core and rest paper, not the steel inside.
    explicit ModeClassifier(const Mesh& mesh, const std::vector<int>& nodes = {}, BodyHeld held = BodyHeld::held);
    // shape: n_nodes x 3 (node-major); lambda_scale as in SolveRequest.
    ModeLabel classify(const std::vector<double>& shape, double lambda, double lambda_scale) const;
    // Share of the shape's mean square (over the looked-at nodes) that its
    // least-squares rigid-body motion t + w x (x - centroid) leaves: 0 for a
    // rigid motion, near 1 for a free body's elastic mode.
    double deformation_share(const std::vector<double>& shape) const;

private:
    int distinct_angles(const std::vector<int>& nodes) const;
    BodyHeld held_;
    std::vector<int> nodes_;                      // looked-at nodes
    std::vector<std::array<double, 3>> offset_;  // their positions from the centroid
    std::vector<double> theta_;
    std::vector<int> station_of_node_;
    std::vector<std::vector<int>> stations_;  // nodes of each station, in z order
};

// Sign changes of a profile along the axis (the axial order m of a mode),
// ignoring values below 5 % of its peak (noise of a nodal point). The solid,
// harmonic and beam levels count m the same way.
// (Inline: the fuzzer's beam level links it without the rest of modes/.)
inline int sign_changes(const std::vector<double>& profile) {
    constexpr double kProfileNoiseShare = 0.05;
    double peak = 0;
    for (double p : profile) peak = std::max(peak, std::abs(p));
    int sign = 0, changes = 0;
    for (double p : profile) {
        if (std::abs(p) < kProfileNoiseShare * peak) continue;
        const int s = p > 0 ? 1 : -1;
        if (sign != 0 && s != sign) ++changes;
        sign = s;
    }
    return changes;
}

}  // namespace coremodal
