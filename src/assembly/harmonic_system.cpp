#include "assembly/harmonic_system.hpp"

#include "common/error.hpp"
#include "effects/support_effects.hpp"
#include "element/harmonic_element.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace coremodal {
namespace {

// Which components are held, which share a DOF: a union-find over the
// 3 * n_nodes components, then a numbering of the free representatives.
class ComponentMap {
public:
    explicit ComponentMap(int n_nodes) : parent_(3 * n_nodes), held_(3 * n_nodes, false) {
        std::iota(parent_.begin(), parent_.end(), 0);
    }
    int find(int c) { return parent_[c] == c ? c : parent_[c] = find(parent_[c]); }
    void tie(int a, int b) { parent_[find(a)] = find(b); }
    void hold(int c) { held_[c] = true; }
    HarmonicDofs number() {
        for (size_t c = 0; c < held_.size(); ++c)
            if (held_[c]) held_[find(static_cast<int>(c))] = true;
        HarmonicDofs dofs;
        dofs.of_component.assign(parent_.size(), -1);
        std::vector<int> dof_of_root(parent_.size(), -1);
        for (size_t c = 0; c < parent_.size(); ++c) {
            const int root = find(static_cast<int>(c));
            if (held_[root]) continue;
            if (dof_of_root[root] < 0) dof_of_root[root] = dofs.n_dofs++;
            dofs.of_component[c] = dof_of_root[root];
        }
        return dofs;
    }

private:
    std::vector<int> parent_;
    std::vector<bool> held_;
};

}  // namespace

HarmonicDofs harmonic_dofs(const Scene& scene, const SectionMesh& mesh, int n, const std::vector<int>& also_held) {
    ComponentMap map(mesh.n_nodes());
    const auto hold_node = [&](int node) {
        for (int c = 0; c < 3; ++c) map.hold(3 * node + c);
    };
    for (int node : also_held) hold_node(node);
    const SupportEffects effects = support_effects(scene);
    for (const RigidClamp& c : effects.clamps)
        for (int node : mesh.node_groups.at("clamp_" + c.name)) hold_node(node);
    for (const ChuckEffects& chuck : effects.chucks) {
        const std::string& name = chuck.placement.chuck;
        if (!chuck.bearing_springs)  // a rigid bearing
            for (const SectionEdge& e : mesh.edge_groups.at("bearing_" + name))
                for (int node : e) hold_node(node);
        if (!chuck.bonded) continue;
        const auto& core = mesh.edge_groups.at("interface_" + name + "_core");
        const auto& body = mesh.edge_groups.at("interface_" + name + "_chuck");
        for (size_t k = 0; k < core.size(); ++k)
            for (int p = 0; p < 3; ++p)
                for (int c = 0; c < 3; ++c) map.tie(3 * core[k][p] + c, 3 * body[k][p] + c);
    }
    if (const auto axis = mesh.node_groups.find("axis"); axis != mesh.node_groups.end())
        for (int node : axis->second) {
            const int u = 3 * node, v = u + 1, w = u + 2;
            if (n == 0) {
                map.hold(u);
                map.hold(v);
            } else if (n == 1) {
                map.hold(w);
                map.tie(v, u);
            } else {
                hold_node(node);
            }
        }
    HarmonicDofs dofs = map.number();
    for (const ChuckEffects& chuck : effects.chucks)
        dofs.frame.push_back(chuck.frame && n <= 1 ? dofs.n_dofs++ : -1);
    return dofs;
}

namespace {

// Element matrices gathered as coordinate entries (PETSc's COO assembly).
// Every term's matrix gets the union pattern of all entries (zeros where a
// term has none), so K - sigma M keeps the pattern it always had.
struct CooEntries {
    std::vector<PetscInt> i, j;
    std::vector<Term> term;
    std::vector<PetscScalar> value;
    void add(Term t, const std::vector<int>& dofs, const Eigen::MatrixXd& A) {
        for (size_t a = 0; a < dofs.size(); ++a)
            for (size_t b = 0; b < dofs.size(); ++b) {
                if (dofs[a] < 0 || dofs[b] < 0) continue;
                i.push_back(dofs[a]);
                j.push_back(dofs[b]);
                term.push_back(t);
                value.push_back(A(a, b));
            }
    }
    std::vector<PetscScalar> values_of(Term t) const {
        std::vector<PetscScalar> v(value.size(), 0.0);
        for (size_t k = 0; k < value.size(); ++k)
            if (term[k] == t) v[k] = value[k];
        return v;
    }
};

std::vector<int> component_dofs(const HarmonicDofs& dofs, const int* nodes, int count) {
    std::vector<int> out;
    for (int a = 0; a < count; ++a)
        for (int c = 0; c < 3; ++c) out.push_back(dofs.of_component[3 * nodes[a] + c]);
    return out;
}

Quad8Coords cell_coords(const SectionMesh& mesh, int c) {
    Quad8Coords x;
    for (int a = 0; a < 8; ++a) x.row(a) << mesh.nodes[mesh.cells[c][a]][0], mesh.nodes[mesh.cells[c][a]][1];
    return x;
}

Eigen::Matrix<double, 3, 2> edge_coords(const SectionMesh& mesh, const SectionEdge& e) {
    Eigen::Matrix<double, 3, 2> x;
    for (int p = 0; p < 3; ++p) x.row(p) << mesh.nodes[e[p]][0], mesh.nodes[e[p]][1];
    return x;
}

// The spring layer (effects/support_effects.hpp), core minus chuck over the
// expanding elements' interface edges: k_n radially, k_t in the bore's tangent plane.
void add_spring_layer(const SectionMesh& mesh, const ChuckEffects& chuck, const HarmonicDofs& dofs, int n,
                      const TermInsert& insert) {
    const auto& core = mesh.edge_groups.at("interface_" + chuck.placement.chuck + "_core");
    const auto& body = mesh.edge_groups.at("interface_" + chuck.placement.chuck + "_chuck");
    const Eigen::Vector3d k = chuck.spring_layer->per_area_cylindrical();
    for (size_t e = 0; e < core.size(); ++e) {
        const Eigen::MatrixXd K = spring_between(harmonic_edge_spring(edge_coords(mesh, core[e]), k, n));
        std::vector<int> d = component_dofs(dofs, core[e].data(), 3);
        const std::vector<int> d_body = component_dofs(dofs, body[e].data(), 3);
        d.insert(d.end(), d_body.begin(), d_body.end());
        insert(SpringLayer::kTerm, d, K);
    }
}

// The bearing springs (effects/support_effects.hpp) spread over the shaft end
// face: c_r on u_r and u_theta, c_z on u_z; relative to the frame DOF where
// there is one (n = 1: U and V follow the frame's sideways motion; n = 0: W
// its axial motion).
void add_bearing(const SectionMesh& mesh, const ChuckEffects& chuck, int frame_dof, const HarmonicDofs& dofs, int n,
                 const TermInsert& insert) {
    const auto& edges = mesh.edge_groups.at("bearing_" + chuck.placement.chuck);
    // The face's area and second moment about a diameter, from its radial edges.
    double area = 0, second_moment = 0;
    for (const SectionEdge& e : edges) {
        const double r0 = std::min(mesh.nodes[e[0]][0], mesh.nodes[e[1]][0]);
        const double r1 = std::max(mesh.nodes[e[0]][0], mesh.nodes[e[1]][0]);
        area += M_PI * (r1 * r1 - r0 * r0);
        second_moment += M_PI / 4 * (std::pow(r1, 4) - std::pow(r0, 4));
    }
    const Eigen::Vector3d c = chuck.bearing_springs->per_face_area(area, second_moment);
    Eigen::VectorXd follow = Eigen::VectorXd::Zero(9);  // face components that move with the frame DOF
    for (int p = 0; p < 3; ++p) {
        if (n == 1) follow[3 * p] = follow[3 * p + 1] = 1;
        if (n == 0) follow[3 * p + 2] = 1;
    }
    for (const SectionEdge& e : edges) {
        const Eigen::Matrix<double, 9, 9> Ke = harmonic_edge_spring(edge_coords(mesh, e), c, n);
        std::vector<int> d = component_dofs(dofs, e.data(), 3);
        if (frame_dof < 0) {
            insert(BearingSprings::kTerm, d, Ke);
            continue;
        }
        Eigen::MatrixXd K(10, 10);  // relative motion u - follow * X: [I, -follow]^T Ke [I, -follow]
        K.topLeftCorner(9, 9) = Ke;
        K.topRightCorner(9, 1) = -Ke * follow;
        K.bottomLeftCorner(1, 9) = -(Ke * follow).transpose();
        K(9, 9) = follow.dot(Ke * follow);
        d.push_back(frame_dof);
        insert(BearingSprings::kTerm, d, K);
    }
    if (frame_dof >= 0) {
        insert(Term::stiffness, {frame_dof}, Eigen::MatrixXd::Constant(1, 1, chuck.frame->stiffness));
        insert(Term::mass, {frame_dof}, Eigen::MatrixXd::Constant(1, 1, chuck.frame->mass));
    }
}

PetscMatrix coo_matrix(MPI_Comm comm, int n_dofs, const CooEntries& t, const std::vector<PetscScalar>& values,
                       bool symmetric = true) {
    // PETSc may reorder the index arrays it is given: each matrix gets its own copy.
    std::vector<PetscInt> i = t.i, j = t.j;
    PetscMatrix A;
    COREMODAL_PETSC(MatCreate(comm, A.out()));
    COREMODAL_PETSC(MatSetSizes(A, PETSC_DECIDE, PETSC_DECIDE, n_dofs, n_dofs));
    COREMODAL_PETSC(MatSetType(A, MATAIJ));
    COREMODAL_PETSC(MatSetPreallocationCOO(A, static_cast<PetscCount>(i.size()), i.data(), j.data()));
    COREMODAL_PETSC(MatSetValuesCOO(A, values.data(), ADD_VALUES));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, symmetric ? PETSC_TRUE : PETSC_FALSE));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRY_ETERNAL, symmetric ? PETSC_TRUE : PETSC_FALSE));
    return A;
}

}  // namespace

double assemble_harmonic_cells(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const HarmonicDofs& dofs, int n, const std::function<bool(int)>& take,
                               const TermInsert& insert) {
    double mass = 0;
    for (int c = 0; c < mesh.n_cells(); ++c) {
        if (!take(c)) continue;
        const PartMaterial& mat = materials.at(mesh.cell_part[c]);
        const HarmonicMatrices e = harmonic_quad8_matrices(cell_coords(mesh, c), mat.C_cylindrical, mat.density, n);
        const std::vector<int> cell_dofs = component_dofs(dofs, mesh.cells[c].data(), 8);
        insert(Term::stiffness, cell_dofs, e.K);
        insert(Term::mass, cell_dofs, e.M);
        mass += e.mass;
    }
    return mass;
}

void assemble_harmonic_spin_terms(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                  const HarmonicDofs& dofs, int n, const TermInsert& insert) {
    for (int c = 0; c < mesh.n_cells(); ++c)
        insert(Term::gyroscopic, component_dofs(dofs, mesh.cells[c].data(), 8),
               harmonic_quad8_spin_coupling(cell_coords(mesh, c), materials.at(mesh.cell_part[c]).density, n));
}

double assemble_harmonic_terms(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const HarmonicDofs& dofs, int n, const TermInsert& insert) {
    double mass = assemble_harmonic_cells(mesh, materials, dofs, n, [](int) { return true; }, insert);
    const SupportEffects effects = support_effects(scene);
    for (size_t k = 0; k < effects.chucks.size(); ++k) {
        const ChuckEffects& chuck = effects.chucks[k];
        if (chuck.spring_layer) add_spring_layer(mesh, chuck, dofs, n, insert);
        if (chuck.bearing_springs) add_bearing(mesh, chuck, dofs.frame[k], dofs, n, insert);
        mass += chuck.frame ? chuck.frame->mass : 0.0;
    }
    return mass;
}

HarmonicSystem assemble_harmonic(const Scene& scene, const SectionMesh& mesh,
                                 const std::vector<PartMaterial>& materials, int n, MPI_Comm comm) {
    HarmonicSystem system;
    system.n = n;
    system.dofs = harmonic_dofs(scene, mesh, n);
    CooEntries entries;
    OperatorSet& ops = system.operators;
    // The section is small (thousands of nodes): rank 0 computes every
    // element; PETSc's COO assembly sends the entries to their owners.
    if (mpi_rank(comm) == 0)
        ops.model_mass = assemble_harmonic_terms(scene, mesh, materials, system.dofs, n,
                                                 [&](Term t, const std::vector<int>& d, const Eigen::MatrixXd& A) {
                                                     entries.add(t, d, A);
                                                 });
    MPI_Bcast(&ops.model_mass, 1, MPI_DOUBLE, 0, comm);
    // Which terms exist is known on rank 0 only; today's terms are stiffness and mass.
    for (Term t : {Term::stiffness, Term::mass})
        ops.matrices[t] = coo_matrix(comm, system.dofs.n_dofs, entries, entries.values_of(t));
    return system;
}

PetscMatrix assemble_harmonic_weighted_stiffness(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                                 const HarmonicDofs& dofs, int n, const std::vector<double>& weight,
                                                 MPI_Comm comm) {
    CooEntries entries;
    if (mpi_rank(comm) == 0)
        for (int c = 0; c < mesh.n_cells(); ++c) {
            const double w = weight.at(mesh.cell_part[c]);
            if (w == 0.0) continue;
            const PartMaterial& mat = materials.at(mesh.cell_part[c]);
            const HarmonicMatrices e = harmonic_quad8_matrices(cell_coords(mesh, c), mat.C_cylindrical, mat.density, n);
            entries.add(Term::stiffness, component_dofs(dofs, mesh.cells[c].data(), 8), w * e.K);
        }
    return coo_matrix(comm, dofs.n_dofs, entries, entries.values_of(Term::stiffness));
}

PetscMatrix assemble_harmonic_spin_coupling(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                            const HarmonicDofs& dofs, int n, MPI_Comm comm) {
    CooEntries entries;
    if (mpi_rank(comm) == 0)
        assemble_harmonic_spin_terms(mesh, materials, dofs, n, [&](Term t, const std::vector<int>& d, const Eigen::MatrixXd& A) {
            entries.add(t, d, A);
        });
    // Symmetric for n >= 1 (it couples the two families), skew for n = 0.
    return coo_matrix(comm, dofs.n_dofs, entries, entries.values_of(Term::gyroscopic), n > 0);
}

std::vector<double> assemble_harmonic_centrifugal_load(const SectionMesh& mesh,
                                                       const std::vector<PartMaterial>& materials,
                                                       const HarmonicDofs& dofs) {
    std::vector<double> f(dofs.n_dofs, 0.0);
    for (int c = 0; c < mesh.n_cells(); ++c) {
        const Eigen::Matrix<double, 24, 1> fe =
            harmonic_quad8_centrifugal_load(cell_coords(mesh, c), materials.at(mesh.cell_part[c]).density);
        const std::vector<int> d = component_dofs(dofs, mesh.cells[c].data(), 8);
        for (int k = 0; k < 24; ++k)
            if (d[k] >= 0) f[d[k]] += fe[k];
    }
    return f;
}

std::vector<SectionStress> harmonic_section_stress(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                                   const HarmonicDofs& dofs, const std::vector<double>& x) {
    std::vector<SectionStress> out;
    out.reserve(mesh.n_cells());
    for (int c = 0; c < mesh.n_cells(); ++c) {
        const std::vector<int> d = component_dofs(dofs, mesh.cells[c].data(), 8);
        Eigen::Matrix<double, 24, 1> u;
        for (int k = 0; k < 24; ++k) u[k] = d[k] >= 0 ? x.at(d[k]) : 0.0;
        out.push_back(harmonic_quad8_stress(cell_coords(mesh, c), materials.at(mesh.cell_part[c]).C_cylindrical, u));
    }
    return out;
}

PetscMatrix assemble_harmonic_centrifugal(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                          const HarmonicDofs& dofs, int n, const std::vector<SectionStress>& stress,
                                          MPI_Comm comm) {
    CooEntries entries;
    if (mpi_rank(comm) == 0)
        for (int c = 0; c < mesh.n_cells(); ++c)
            entries.add(Term::centrifugal, component_dofs(dofs, mesh.cells[c].data(), 8),
                        harmonic_quad8_centrifugal(cell_coords(mesh, c), materials.at(mesh.cell_part[c]).density,
                                                   stress.at(c), n));
    return coo_matrix(comm, dofs.n_dofs, entries, entries.values_of(Term::centrifugal));
}

std::vector<double> harmonic_rigid_field(const SectionMesh& mesh, const HarmonicDofs& dofs, int n, RigidMotion motion) {
    std::vector<double> r(dofs.n_dofs, 0.0);
    const int lives_in = motion == RigidMotion::x ? 1 : 0;  // sideways: n = 1; along and about z: n = 0
    if (n != lives_in) return r;
    for (int node = 0; node < mesh.n_nodes(); ++node)
        for (int c = 0; c < 3; ++c) {
            const int d = dofs.of_component[3 * node + c];
            if (d < 0) continue;
            if (motion == RigidMotion::x && c < 2) r[d] = 1;
            if (motion == RigidMotion::z && c == 2) r[d] = 1;
            if (motion == RigidMotion::rz && c == 1) r[d] = mesh.nodes[node][0];
        }
    for (int d : dofs.frame)
        if (d >= 0 && motion != RigidMotion::rz) r[d] = 1;  // the frame translates with the body
    return r;
}

}  // namespace coremodal
