// The coupled problem's assembly: each block's harmonic terms on the
// scene with full bands, then what couples the blocks (the one-sided
// contact's layer, the web's line, the pads' deviation from the band),
// summed into PETSc's COO matrices (models/coupled/coupled_system.hpp).
#include "models/coupled/coupled_system.hpp"

#include "common/error.hpp"
#include "effects/chuck_placement.hpp"
#include "effects/web.hpp"

#include <algorithm>
#include <cstdint>

namespace coremodal {

namespace {

std::vector<int> shifted(std::vector<int> dofs, int offset) {
    for (int& d : dofs)
        if (d >= 0) d += offset;
    return dofs;
}

// The global DOFs of a section edge's three nodes (U, V, W each) in a block.
std::vector<int> edge_dofs(const CoupledBlock& block, const SectionEdge& e) {
    std::vector<int> out;
    for (int p = 0; p < 3; ++p)
        for (int c = 0; c < 3; ++c) {
            const int d = block.dofs.of_component[3 * e[p] + c];
            out.push_back(d < 0 ? -1 : d + block.offset);
        }
    return out;
}

// The pad layer's deviation from the full band on one interface edge pair:
// k_c (I_pads - I_band)(a, b) int N_i N_j r ds on core minus chuck, for
// every pair of blocks it couples (the diagonal pairs included: there it
// takes the band's share of the pads' gaps away).
void add_pad_coupling(const SectionMesh& mesh, const PadLayer& pad, const SectionEdge& core, const SectionEdge& body,
                      const CoupledDofs& dofs, const CoupledInsert& insert) {
    Eigen::Matrix<double, 3, 2> x;
    for (int p = 0; p < 3; ++p) x.row(p) << mesh.nodes[core[p]][0], mesh.nodes[core[p]][1];
    // int N_i N_j diag(k) r ds: harmonic_edge_spring's w_n = pi for n = 1 taken out.
    const Eigen::Matrix<double, 9, 9> edge = harmonic_edge_spring(x, pad.layer.per_area_cylindrical(), 1) / M_PI;
    const Eigen::MatrixXd between = spring_between(edge);  // 18 x 18, node-major (U, V, W) on core then chuck
    const std::vector<Arc> band = {{0, 2 * M_PI}};
    for (const CoupledBlock& a : dofs.blocks)
        for (const CoupledBlock& b : dofs.blocks) {
            std::array<double, 3> scale{};
            bool any = false;
            for (int c = 0; c < 3; ++c) {
                scale[c] = pad_integral(pad.arcs, a.harmonic, b.harmonic, c) -
                           pad_integral(band, a.harmonic, b.harmonic, c);
                any = any || scale[c] != 0;
            }
            if (!any) continue;
            Eigen::MatrixXd K = between;
            for (int i = 0; i < 18; ++i) K.row(i) *= scale[i % 3];  // diag(k): rows and columns share a component
            std::vector<int> rows = edge_dofs(a, core), cols = edge_dofs(b, core);
            const std::vector<int> rows_body = edge_dofs(a, body), cols_body = edge_dofs(b, body);
            rows.insert(rows.end(), rows_body.begin(), rows_body.end());
            cols.insert(cols.end(), cols_body.begin(), cols_body.end());
            insert(SpringLayer::kTerm, rows, cols, K);
        }
}

// The web's line on one edge of the roll's outer surface (r constant):
// int N_i N_j dz B_a^T K_line B_b for every pair of blocks it couples.
void add_web_coupling(const SectionMesh& mesh, const WebLine& web, const SectionEdge& edge, const CoupledDofs& dofs,
                      const CoupledInsert& insert) {
    Eigen::Matrix<double, 3, 2> x;
    for (int p = 0; p < 3; ++p) x.row(p) << mesh.nodes[edge[p]][0], mesh.nodes[edge[p]][1];
    // int N_i N_j r ds (times the identity, node-major): harmonic_edge_spring's w_n = pi for n = 1 and r taken out.
    const Eigen::Matrix<double, 9, 9> weights = harmonic_edge_spring(x, Eigen::Vector3d::Ones(), 1) / (M_PI * x(0, 0));
    for (const CoupledBlock& a : dofs.blocks)
        for (const CoupledBlock& b : dofs.blocks) {
            const Eigen::Matrix3d k = web_between(web, a.harmonic, b.harmonic);
            if (k.cwiseAbs().maxCoeff() <= kVanishingShare * web.stiffness.norm()) continue;
            Eigen::MatrixXd K(9, 9);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) K.block<3, 3>(3 * i, 3 * j) = weights(3 * i, 3 * j) * k;
            insert(Term::stiffness, edge_dofs(a, edge), edge_dofs(b, edge), K);
        }
}

// The one-sided contact's layer on each interface edge pair of its chucks:
// contact_edge_matrix between every pair of blocks it couples, on core minus chuck.
void add_contact_coupling(const SectionMesh& mesh, const SupportEffects& effects, const ContactLayer& layer,
                          const CoupledDofs& dofs, const CoupledInsert& insert) {
    for (size_t first = 0, last = 0; first < layer.points.size(); first = last) {
        const HarmonicContactPoint& p = layer.points[first];
        for (last = first; last < layer.points.size() && layer.points[last].bore.chuck == p.bore.chuck &&
                           layer.points[last].edge == p.edge;
             ++last) {
        }
        const std::string& chuck = effects.chucks.at(p.bore.chuck).placement.chuck;
        const SectionEdge& core = mesh.edge_groups.at("interface_" + chuck + "_core").at(p.edge);
        const SectionEdge& body = mesh.edge_groups.at("interface_" + chuck + "_chuck").at(p.edge);
        for (const CoupledBlock& a : dofs.blocks)
            for (const CoupledBlock& b : dofs.blocks) {
                const Eigen::Matrix<double, 9, 9> edge = contact_edge_matrix(layer, first, last, a.harmonic, b.harmonic);
                if (edge.isZero(0)) continue;
                std::vector<int> rows = edge_dofs(a, core), cols = edge_dofs(b, core);
                const std::vector<int> rows_body = edge_dofs(a, body), cols_body = edge_dofs(b, body);
                rows.insert(rows.end(), rows_body.begin(), rows_body.end());
                cols.insert(cols.end(), cols_body.begin(), cols_body.end());
                insert(OneSidedContact::kTerm, rows, cols, spring_between(edge));
            }
    }
}

}  // namespace

double assemble_coupled_terms(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                              const CoupledDofs& dofs, const CoupledInsert& insert) {
    return assemble_coupled_terms(scene, mesh, materials, dofs, attachments(scene), insert);
}

double assemble_coupled_terms(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                              const CoupledDofs& dofs, const Attachments& attached, const CoupledInsert& insert) {
    const Scene band = with_full_bands(scene);
    double mass = 0;
    for (const CoupledBlock& block : dofs.blocks) {
        const double m = assemble_harmonic_terms(
            band, mesh, materials, block.dofs, block.harmonic.n,
            [&](Term t, const std::vector<int>& d, const Eigen::MatrixXd& A) {
                const std::vector<int> g = shifted(d, block.offset);
                insert(t, g, g, A);
            });
        if (block.harmonic.n == 0) mass = m;
    }
    COREMODAL_ASSERT(!attached.one_sided || attached.contact);  // the level solves the static state first
    if (attached.contact) add_contact_coupling(mesh, support_effects(scene), *attached.contact, dofs, insert);
    if (attached.web)
        for (const SectionEdge& e : mesh.edge_groups.at("roll_outer")) add_web_coupling(mesh, *attached.web, e, dofs, insert);
    for (const PadLayer& pad : attached.pads) {
        const auto& core = mesh.edge_groups.at("interface_" + pad.chuck + "_core");
        const auto& body = mesh.edge_groups.at("interface_" + pad.chuck + "_chuck");
        for (size_t e = 0; e < core.size(); ++e) {
            const double z = mesh.nodes[core[e][2]][1];  // the middle node
            if (pad.zone.holds(z, 0)) add_pad_coupling(mesh, pad, core[e], body[e], dofs, insert);
        }
    }
    return mass;
}

CoupledSystem assemble_coupled(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const CoupledDofs& dofs, MPI_Comm comm) {
    return assemble_coupled(scene, mesh, materials, dofs, attachments(scene), comm);
}

namespace {

// The symmetric n x n AIJ matrix of the coordinate entries (i, j, values),
// duplicates added; i and j are copies: PETSc may reorder the arrays it is given.
PetscMatrix symmetric_coo_matrix(MPI_Comm comm, PetscInt n, std::vector<PetscInt> i, std::vector<PetscInt> j,
                                 const std::vector<PetscScalar>& values) {
    PetscMatrix A;
    COREMODAL_PETSC(MatCreate(comm, A.out()));
    COREMODAL_PETSC(MatSetSizes(A, PETSC_DECIDE, PETSC_DECIDE, n, n));
    COREMODAL_PETSC(MatSetType(A, MATAIJ));
    COREMODAL_PETSC(MatSetPreallocationCOO(A, static_cast<PetscCount>(i.size()), i.data(), j.data()));
    COREMODAL_PETSC(MatSetValuesCOO(A, values.data(), ADD_VALUES));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    return A;
}

}  // namespace

CoupledSystem assemble_coupled(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const CoupledDofs& dofs, const Attachments& attached, MPI_Comm comm) {
    CoupledSystem system;
    system.dofs = dofs;
    // Coordinate entries for PETSc's COO assembly; every term gets the union
    // pattern (zeros where it has none), so K - sigma M keeps one pattern.
    // The element entries (millions at N ~ 20) are summed here first: sorting
    // 64-bit keys is cheaper than PETSc's preallocation of every duplicate.
    struct Entry {
        std::int64_t key;  // row * n_dofs + column
        double k, m;
    };
    std::vector<Entry> raw;
    const std::int64_t n = system.dofs.n_dofs;
    if (mpi_rank(comm) == 0) {
        system.operators.model_mass = assemble_coupled_terms(
            scene, mesh, materials, system.dofs, attached,
            [&](Term t, const std::vector<int>& rows, const std::vector<int>& cols, const Eigen::MatrixXd& A) {
                for (size_t a = 0; a < rows.size(); ++a)
                    for (size_t b = 0; b < cols.size(); ++b) {
                        if (rows[a] < 0 || cols[b] < 0 || A(a, b) == 0) continue;
                        raw.push_back({rows[a] * n + cols[b], t == Term::stiffness ? A(a, b) : 0.0,
                                       t == Term::mass ? A(a, b) : 0.0});
                    }
            });
        std::sort(raw.begin(), raw.end(), [](const Entry& x, const Entry& y) { return x.key < y.key; });
    }
    std::vector<PetscInt> i, j;
    std::vector<PetscScalar> k_values, m_values;
    for (size_t e = 0; e < raw.size(); ++e) {
        if (e > 0 && raw[e].key == raw[e - 1].key) {
            k_values.back() += raw[e].k;
            m_values.back() += raw[e].m;
            continue;
        }
        i.push_back(static_cast<PetscInt>(raw[e].key / n));
        j.push_back(static_cast<PetscInt>(raw[e].key % n));
        k_values.push_back(raw[e].k);
        m_values.push_back(raw[e].m);
    }
    raw = {};
    const auto block_of_dof = [&](int d) {
        int b = 0;
        while (b + 1 < static_cast<int>(system.dofs.blocks.size()) && system.dofs.blocks[b + 1].offset <= d) ++b;
        return b;
    };
    for (size_t e = 0; e < i.size(); ++e)
        if (k_values[e] != 0 && block_of_dof(static_cast<int>(i[e])) != block_of_dof(static_cast<int>(j[e])))
            ++system.n_coupling_entries;
    MPI_Bcast(&system.operators.model_mass, 1, MPI_DOUBLE, 0, comm);
    for (Term t : {Term::stiffness, Term::mass})
        system.operators.matrices[t] =
            symmetric_coo_matrix(comm, system.dofs.n_dofs, i, j, t == Term::stiffness ? k_values : m_values);
    return system;
}

}  // namespace coremodal
