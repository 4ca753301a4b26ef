// The steady stress of a spinning body of revolution (effects/rotation.hpp,
// docs/theory/rotation.md "Centrifugal stiffening"): the axisymmetric (n = 0)
// static solve K_0 u_1 = f_1 under the body force rho r e_r per unit
// Omega^2 on every section cell, with the scene's supports (clamps held,
// spring layers and bearings as at rest), and its stress at every Gauss
// point. The stress is linear in Omega^2: sigma_0 = Omega^2 sigma_1.
//
// A free scene's K_0 is singular (axial translation, rotation about z). The
// load is orthogonal to both motions, so one DOF is held for each motion K_0
// leaves free: its reaction r^T f_1 is zero and the answer is exact.
//
// The section is small (thousands of DOFs): the solve is a sparse LDL^T on
// rank 0, where the harmonic level computes every element.
#pragma once

#include "assembly/cell_loop.hpp"
#include "element/harmonic_element.hpp"
#include "geometry/section_mesh.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace coremodal {

struct CentrifugalPrestress {
    std::vector<SectionStress> stress;  // per section cell, Pa per (rad/s)^2
    std::vector<double> displacement;   // u_1 on the n = 0 DOFs, m per (rad/s)^2
    int held_rigid_motions = 0;         // 0 (supported), up to 2 (free: along and about z)
    double relative_residual = 0;       // ||K_0 u_1 - f_1|| / ||f_1||
};

// Throws SolveError when K_0 cannot be factored (a mechanism beyond the two
// rigid motions) or the solve's residual is not small.
CentrifugalPrestress centrifugal_prestress(const Scene& scene, const SectionMesh& mesh,
                                           const std::vector<PartMaterial>& materials);

}  // namespace coremodal
