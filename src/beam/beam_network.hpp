// A network of Timoshenko beams on the z axis: beams (chains of nodes),
// distributed spring layers between two beams, springs at nodes, point
// masses and held DOFs; assembled into sparse K and M on the free DOFs.
// Knows nothing of scenes (beam_model.hpp builds a network from a Scene).
//
// Every node has the six DOFs of timoshenko_element.hpp; a node may belong to
// two beams (that ties them: shared DOFs, no penalty). Held DOFs are
// eliminated, never penalised (DESIGN.md).
#pragma once

#include "beam/timoshenko_element.hpp"
#include "material/material.hpp"  // Matrix6

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <string>
#include <vector>

namespace coremodal {

// The four kinds of motion a network DOF belongs to. A beam on the z axis
// never couples them; only an asymmetric spring layer can.
enum class MotionFamily { bending_xz, bending_yz, axial, torsion };
constexpr int kMotionFamilies = 4;
MotionFamily motion_family(int network_dof);  // network_dof = 6 * node + beam_dof::...

struct BeamNetwork {
    // A chain of nodes in ascending z; element e has nodes[2e] and
    // nodes[2e + 2] at its ends and nodes[2e + 1] halfway between them.
    struct Beam {
        std::string name;
        std::vector<int> nodes;
        std::vector<BeamSection> sections;  // one per element
    };
    // A spring layer between two beams over z_start..z_end: energy per unit
    // length 1/2 d^T k d, d = (motion of beam b) - (motion of beam a), both
    // interpolated with their own elements' shape functions; beam_b = -1 ties
    // beam a to the ground (a web's span, a foundation): d = -(motion of a).
    struct Coupling {
        int beam_a = 0, beam_b = 0;
        double z_start = 0, z_end = 0;  // m
        Matrix6 stiffness_per_length;   // on (ux, uy, uz, rx, ry, rz): N/m^2, N/rad, N m/rad per m
    };
    // A spring on the six DOFs of node_a, to ground (node_b = -1) or to node_b.
    struct Spring {
        int node_a = 0, node_b = -1;
        Matrix6 stiffness;  // N/m, N m/rad
    };
    // A lumped mass at a node, moving with its translations (no rotary inertia).
    struct PointMass {
        int node = 0;
        double mass = 0;  // kg
    };

    std::vector<double> node_z;  // m
    std::vector<Beam> beams;
    std::vector<Coupling> couplings;
    std::vector<Spring> springs;
    std::vector<PointMass> masses;
    std::vector<bool> held;  // per DOF: 6 * node + beam_dof::...

    int add_node(double z);
    // A beam with element ends at z_ends (ascending); node_at(z) supplies the
    // node at every z of the chain, ends and middles: a new one (add_node), or
    // another beam's node there to tie the two. Returns the beam's index.
    template <typename NodeAt>
    int add_beam(std::string name, const std::vector<double>& z_ends, std::vector<BeamSection> sections,
                 NodeAt node_at);
    void hold(int node, int dof) { held[beam_dof::per_node * node + dof] = true; }
    void hold_all(int node);
    int n_nodes() const { return static_cast<int>(node_z.size()); }
    int n_elements() const;
    // Sum of rho A over the elements and the point masses, kg.
    double mass() const;
};

// K and M on free DOFs (all of them, or those of some families), numbered
// node by node along z: banded. K and M share one sparsity pattern (explicit
// zeros), so K - lambda M is a sum of their value arrays.
struct NetworkMatrices {
    Eigen::SparseMatrix<double> K, M;
    std::vector<int> free_dofs;  // network DOF (6 * node + dof) of each row
};

// A set of motion families, bit f for MotionFamily f.
using FamilySet = unsigned;
constexpr FamilySet kAllFamilies = 0b1111;
FamilySet family_bit(MotionFamily f);

// The family sets that can be solved apart: beams and point masses never
// couple families; springs and spring layers may (a pad on one side couples
// sideways motion with twist). Rounding-level entries do not count.
std::vector<FamilySet> independent_family_sets(const BeamNetwork& network);

// True when the y-z bending problem is the x-z one (every spring acts alike
// in both planes and the same DOFs are held): then one solve gives both
// members of every bending pair.
bool bending_planes_alike(const BeamNetwork& network);

// K and M of each family set, on its free DOFs, assembled in one pass.
std::vector<NetworkMatrices> assemble_problems(const BeamNetwork& network, const std::vector<FamilySet>& sets);

// Sparse LDL^T without a fill-reducing ordering: the free DOFs are already
// numbered along z, so the factor stays inside the band.
using BandedLDLT = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>;

template <typename NodeAt>
int BeamNetwork::add_beam(std::string name, const std::vector<double>& z_ends, std::vector<BeamSection> sections,
                          NodeAt node_at) {
    Beam beam{std::move(name), {}, std::move(sections)};
    for (size_t i = 0; i < z_ends.size(); ++i) {
        if (i > 0) beam.nodes.push_back(node_at(0.5 * (z_ends[i - 1] + z_ends[i])));
        beam.nodes.push_back(node_at(z_ends[i]));
    }
    beams.push_back(std::move(beam));
    return static_cast<int>(beams.size()) - 1;
}

// All free DOFs as one system (tests and checks; the solver assembles by
// problem). Throws std::logic_error (COREMODAL_ASSERT) on an inconsistent
// network: the builder, not the user, is at fault then.
NetworkMatrices assemble_network(const BeamNetwork& network);

}  // namespace coremodal
