// A harmonic field shown on the revolved section: the values of wave number
// n's DOFs for its two families (element/harmonic_element.hpp)
//   cos: u_r = U cos n theta, u_theta = -V sin n theta, u_z = W cos n theta
//   sin: u_r = U sin n theta, u_theta =  V cos n theta, u_z = W sin n theta
// (the sin family is the cos family turned by pi / 2n; n = 0 has one family)
// turned into Cartesian displacements at every node of the revolved mesh,
// and the frame masses' motion at their nodes. The harmonic level draws its
// modes with it; the spinning harmonic level its travelling waves' snapshots.
#pragma once

#include "assembly/harmonic_system.hpp"
#include "geometry/section_mesh.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace coremodal {

// Far beyond any physical band of a roll: reaching it means a wrong input.
constexpr int kMaxHarmonic = 64;
// Cells around the revolved mesh the modes are named and drawn on, at most:
// 32 quadratic cells (64 node angles) resolve every wave number the
// classifier looks for (kMaxWaveNumber = 8) and draw smoothly; finer mesh
// levels refine the section, not this picture (at 64 around naming and
// writing took half of a very fine run).
constexpr int kMaxDisplayAround = 32;

// The frame nodes add_frame_nodes made, per scene chuck (-1: no frame mass).
std::vector<int> frame_nodes_of(const Scene& scene, const Mesh& mesh);

// Node-major (x, y, z) displacements of every revolved node for the
// amplitudes `cos_values` and `sin_values` (per DOF of `dofs`; sin_values
// empty for none). A frame DOF moves its frame node along x (cos) and y
// (sin) in n = 1, along z in n = 0.
std::vector<double> revolved_field(const RevolvedMesh& revolved, const HarmonicDofs& dofs, int n,
                                   const std::vector<double>& cos_values, const std::vector<double>& sin_values,
                                   const std::vector<int>& frame_nodes);

}  // namespace coremodal
