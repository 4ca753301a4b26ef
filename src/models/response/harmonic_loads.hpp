// The harmonic level's sideways problem for the forced response
// (docs/theory/response.md, "At the harmonic level"): wave number n = 1 of the r-z
// section as sparse matrices (K, M, G = 2 Gamma: modal_response.hpp), the
// probes as linear functionals of its DOFs, and the loads of [excitation]
// on it, each the θ-integral of the beam level's load (effects/excitation.hpp):
//
//   unbalance        U Omega^2 at the core's cross-section at mid-core
//   eccentricity     e Omega^2 M_rp r_x: the rest paper's mass times e Omega^2, sideways
//   bow              K_roll u_bow: the core's and rest paper's cells, bowed axis u_bow
//                    (U = V = w(z), W = -r w'(z): plane sections, no shear)
//   ovality_gravity  eps K_core u_sag, at twice the speed (the core's cells alone)
//   gravity          the static sag K^-1 g M r_x (reported)
//
// with r_x the sideways translation (U = V = 1, the frames along). A load is
// the cos family's part p of one turning forward, (p, -i p).
#pragma once

#include "models/response/modal_response.hpp"
#include "models/response/modal_response_model.hpp"
#include "models/response/response_damping.hpp"
#include "assembly/harmonic_system.hpp"
#include "geometry/section_mesh.hpp"
#include "material/material.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene.hpp"

#include <Eigen/Sparse>

#include <vector>

namespace coremodal {

// Wave number n = 1 of the scene's section, on the DOFs of one family.
struct HarmonicPlane {
    SectionMesh section;
    std::vector<PartMaterial> materials;
    HarmonicDofs dofs;
    Eigen::SparseMatrix<double> K, M, G;  // the whole model; G per unit Omega (2 Gamma)
    Eigen::SparseMatrix<double> K_roll;   // the core's and rest paper's cells alone
    Eigen::SparseMatrix<double> K_core;   // the core's cells alone
    Eigen::SparseMatrix<double> M_rest_paper;
};
// The scene must be a body of revolution (require_axisymmetric).
HarmonicPlane assemble_harmonic_plane(const Scene& scene);

// The sideways displacement of the core's cross-section at z (from the
// core's left end) as weights on the DOFs: u_x = w . a, the area mean of
// (U + V) / 2 over the wall (the mean of u_x over the ring is (U + V) / 2),
// the harmonic level's "axis of the core". A force F at that section does
// the work F w . a, so F w is its load.
Eigen::VectorXd section_probe(const HarmonicPlane& plane, double z);

// first_mode: the first bending mode at rest per DOF (bow_shape = "first_mode" only).
LevelLoads build_harmonic_loads(const Scene& scene, const ExcitationSpec& excitation, const HarmonicPlane& plane,
                                   const ModalResponse& response, const Eigen::VectorXd& first_mode);

// Each part's stiffness: its cells' K of wave number n = 1 (the plane outlives it).
PartStiffness harmonic_part_stiffness(const HarmonicPlane& plane);

}  // namespace coremodal
