// Mesh-independent mode signatures and the modal assurance criterion (MAC).
//
// Two study points with different geometry have different meshes, so their
// mode shapes cannot be compared node by node. Each mode is therefore reduced
// to a signature on a fixed grid of the core's outer surface: at
// kSignatureStations stations z/Lc = 0, 1/32, ..., 1 and for each cylindrical
// displacement component (u_r, u_theta, u_z), the Fourier coefficients in
// theta up to harmonic kSignatureHarmonics. The coefficients are scaled
// (sqrt(2 pi) for n = 0, sqrt(pi) for n >= 1, times sqrt of the station's
// share of the length) so that the dot product of two signatures approximates
// the integral of u_a . u_b over the core's outer surface: the MAC of two
// signatures is then the MAC of the two displacement fields, whatever the mesh.
//
// A model level that has no 3D mesh (a beam) can fill the same layout from its
// own shape functions (signature_index); a Mode whose signature is empty is
// compared by its label instead (tracking.hpp).
#pragma once

#include "mesh/mesh.hpp"

#include <vector>

namespace coremodal {

using Signature = std::vector<double>;

constexpr int kSignatureStations = 33;  // z/Lc = s / 32: resolves ~10 axial half-waves
constexpr int kSignatureHarmonics = 6;  // n = 0..6: every family the lowest modes of a core show
constexpr int kSignatureCoefficients = 2 * kSignatureHarmonics + 1;  // a0, a1, b1, ..., a6, b6
constexpr int kSignatureComponents = 3;                              // r, theta, z
constexpr int kSignatureSize = kSignatureStations * kSignatureComponents * kSignatureCoefficients;

// Position in a signature of station s, component c (0 r, 1 theta, 2 z) and
// coefficient k (0: a0; 2n - 1: a_n (cos n theta); 2n: b_n (sin n theta)).
constexpr int signature_index(int station, int component, int coefficient) {
    return (station * kSignatureComponents + component) * kSignatureCoefficients + coefficient;
}

// Builds signatures for every mode of one mesh. The outer surface of the core
// is the node group "core_outer" when the mesh has it (generated meshes), else
// the nodes of part "core" at its largest radius. Nodes are grouped in rings
// of equal z; each ring is fitted by least squares in theta up to the highest
// harmonic its distinct angles resolve, and each harmonic is interpolated
// linearly in z to the stations from the rings that resolve it.
class ModeSignatureSampler {
public:
    explicit ModeSignatureSampler(const Mesh& mesh);
    // shape: n_nodes x 3 (node-major), as Mode::shape. Returns kSignatureSize values.
    Signature operator()(const std::vector<double>& shape) const;

    struct Ring {
        double z = 0;  // normalised, z / Lc in [0, 1]
        std::vector<int> nodes;
        std::vector<double> theta;
        int n_max = 0;  // highest harmonic this ring resolves
    };

private:
    std::vector<Ring> rings_;  // in z order
};

// MAC = |a.b|^2 / ((a.a)(b.b)); 0 when either is zero.
double mac(const Signature& a, const Signature& b);

// MAC of two subspaces (a degenerate pair is a 2D subspace: its members are
// any rotation of each other): ||Qa^T Qb||_F^2 / max(dim a, dim b), with Qa, Qb
// orthonormal bases of the spans. 1 for the same subspace, 0 for orthogonal
// ones; for single vectors it is the MAC above. A member of a pair against the
// pair gives 1/2: a change of multiplicity shows as a poor match.
double subspace_mac(const std::vector<Signature>& a, const std::vector<Signature>& b);

}  // namespace coremodal
