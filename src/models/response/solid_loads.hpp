// The solid level's model for the forced response (docs/theory/response.md, "At
// the solid level"): the solid run's mesh, DOF map and couplings with the
// cells' gyroscopic term as sparse matrices (G skew, both planes: the
// gyroscopic unit i of modal_response.hpp), the probes as weights on the
// DOFs, and the loads of [excitation] as nodal forces. A load turning
// forward is p_x - i p_y: its pattern in the x-z plane and, a quarter turn
// later, in the y-z plane (effects/excitation.hpp):
//
//   unbalance        U Omega^2 on the core's cross-section at mid-core
//   eccentricity     e Omega^2 M_rp r: the rest paper's cells' mass, sideways
//   bow              K_roll u_bow element by element over the core's and rest
//                    paper's cells, u_x = w(z), u_z = -x w'(z) (and y), held
//                    nodes included (a clamped bore is straightened by the load)
//   ovality_gravity  eps K_core u_sag, at twice the speed (the core's cells)
//   gravity          the static sag K^-1 g M r_x (reported)
#pragma once

#include "models/response/modal_response.hpp"
#include "models/response/modal_response_model.hpp"
#include "models/response/response_damping.hpp"
#include "assembly/chuck_supports.hpp"
#include "assembly/dof_map.hpp"
#include "material/material.hpp"
#include "mesh/mesh.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene.hpp"

#include <Eigen/Sparse>

#include <vector>

namespace coremodal {

struct SolidResponseModel {
    Mesh mesh;
    ChuckSupports chucks;
    DofMap dofs;
    std::vector<PartMaterial> materials;
    Eigen::SparseMatrix<double> K, M, G;  // the whole solid; G per unit Omega (skew)
    Eigen::SparseMatrix<double> K_roll;   // the core's and rest paper's cells alone
    Eigen::SparseMatrix<double> K_core;   // the core's cells alone
    Eigen::SparseMatrix<double> M_rest_paper;
};
// The scene must be a body of revolution (why_not_axisymmetric).
SolidResponseModel assemble_solid_response_model(const Scene& scene);

// The mean u_x and u_y of the core's cross-section at z (from the core's
// left end): the core's nodes of the two node layers around z, each layer
// its nodes' plain mean, interpolated linearly in z. A force F along x at
// that section does the work F x . a, so F x is its load.
ProbeWeights solid_section_probe(const SolidResponseModel& model, double z);

// first_pair: the two members of the first bending pair at rest (columns),
// for bow_shape = "first_mode" only (else empty).
LevelLoads build_solid_loads(const Scene& scene, const ExcitationSpec& excitation, const SolidResponseModel& model,
                             const ModalResponse& response, const Eigen::MatrixXd& first_pair);

// Each part's stiffness: its cells' K (the model outlives it).
PartStiffness solid_part_stiffness(const SolidResponseModel& m);

}  // namespace coremodal
