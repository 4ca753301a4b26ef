#include "assembly/petsc_system.hpp"

#include "common/error.hpp"

#include <algorithm>

namespace coremodal {
namespace {

// Every element (cells, then couplings) as a node list, and the inverse:
// node -> elements, in compressed rows.
struct ElementGraph {
    std::vector<int> element_offset, element_nodes;
    std::vector<int> node_offset, node_elements;
};

ElementGraph element_graph(const Mesh& mesh, const std::vector<CouplingElement>& couplings) {
    ElementGraph g;
    g.element_offset.push_back(0);
    const int npc = mesh.nodes_per_cell();
    g.element_nodes = mesh.cells;
    for (int c = 0; c < mesh.n_cells(); ++c) g.element_offset.push_back((c + 1) * npc);
    for (const CouplingElement& e : couplings) {
        g.element_nodes.insert(g.element_nodes.end(), e.nodes.begin(), e.nodes.end());
        g.element_offset.push_back(static_cast<int>(g.element_nodes.size()));
    }
    const int n_elements = static_cast<int>(g.element_offset.size()) - 1;
    g.node_offset.assign(mesh.n_nodes() + 1, 0);
    for (int v : g.element_nodes) ++g.node_offset[v + 1];
    for (int n = 0; n < mesh.n_nodes(); ++n) g.node_offset[n + 1] += g.node_offset[n];
    g.node_elements.resize(g.element_nodes.size());
    std::vector<int> fill(g.node_offset.begin(), g.node_offset.end() - 1);
    for (int e = 0; e < n_elements; ++e)
        for (int k = g.element_offset[e]; k < g.element_offset[e + 1]; ++k)
            g.node_elements[fill[g.element_nodes[k]]++] = e;
    return g;
}

// Number of free-node blocks in each owned block row, split into columns
// owned here (diagonal block) and elsewhere (off-diagonal). A row gathers
// the elements of every mesh node that shares its DOFs (tied nodes).
void count_block_nonzeros(const Mesh& mesh, const std::vector<CouplingElement>& couplings, const DofMap& dofs,
                          int first, int last, std::vector<PetscInt>& d_nnz, std::vector<PetscInt>& o_nnz) {
    const ElementGraph g = element_graph(mesh, couplings);
    const auto free_node_of = [&](int n) { return dofs.node_first_dof[n] < 0 ? -1 : dofs.node_first_dof[n] / 3; };
    std::vector<std::vector<int>> row_nodes(last - first);
    for (int n = 0; n < mesh.n_nodes(); ++n)
        if (const int row = free_node_of(n); row >= first && row < last) row_nodes[row - first].push_back(n);
    d_nnz.assign(last - first, 0);
    o_nnz.assign(last - first, 0);
    std::vector<int> seen(dofs.n_free_nodes, -1);
    for (int row = first; row < last; ++row)
        for (int n : row_nodes[row - first])
            for (int k = g.node_offset[n]; k < g.node_offset[n + 1]; ++k) {
                const int e = g.node_elements[k];
                for (int j = g.element_offset[e]; j < g.element_offset[e + 1]; ++j) {
                    const int col = free_node_of(g.element_nodes[j]);
                    if (col < 0 || seen[col] == row) continue;
                    seen[col] = row;
                    ++((col >= first && col < last) ? d_nnz : o_nnz)[row - first];
                }
            }
}

PetscMatrix create_matrix(MPI_Comm comm, int n_local_dofs, const std::vector<PetscInt>& d_nnz,
                          const std::vector<PetscInt>& o_nnz) {
    PetscMatrix A;
    COREMODAL_PETSC(MatCreate(comm, A.out()));
    COREMODAL_PETSC(MatSetSizes(A, n_local_dofs, n_local_dofs, PETSC_DETERMINE, PETSC_DETERMINE));
    COREMODAL_PETSC(MatSetType(A, MATAIJ));
    COREMODAL_PETSC(MatSetBlockSize(A, 3));
    COREMODAL_PETSC(MatXAIJSetPreallocation(A, 3, d_nnz.data(), o_nnz.data(), nullptr, nullptr));
    // A preallocation bug must fail loudly, not silently slow assembly 100x.
    COREMODAL_PETSC(MatSetOption(A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
    return A;
}

}  // namespace

OperatorSet assemble_petsc(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                           const std::vector<CouplingElement>& couplings, MPI_Comm comm,
                           const std::vector<Term>& extra_terms) {
    const int rank = mpi_rank(comm), size = mpi_size(comm);
    // Named variables, not a structured binding: the lambda below captures
    // them, which clang 14 (the sanitizer build) does not allow for bindings.
    const auto owned = owned_free_nodes(dofs.n_free_nodes, rank, size);
    const int first = owned.first, last = owned.second;
    std::vector<PetscInt> d_nnz, o_nnz;
    count_block_nonzeros(mesh, couplings, dofs, first, last, d_nnz, o_nnz);

    OperatorSet system;
    std::vector<Term> terms = {Term::stiffness, Term::mass};
    terms.insert(terms.end(), extra_terms.begin(), extra_terms.end());
    for (const CouplingElement& e : couplings)
        for (const TermMatrix& t : e.terms)
            if (std::find(terms.begin(), terms.end(), t.term) == terms.end()) terms.push_back(t.term);
    for (Term t : terms) system.matrices[t] = create_matrix(comm, 3 * (last - first), d_nnz, o_nnz);

    // An element is assembled by the rank owning its lowest-numbered free node.
    auto owned_here = [&](const int* nodes, int n) {
        int lowest = dofs.n_free_nodes;
        for (int a = 0; a < n; ++a) {
            const int d = dofs.node_first_dof[nodes[a]];
            if (d >= 0) lowest = std::min(lowest, d / 3);
        }
        if (lowest == dofs.n_free_nodes) return rank == 0;  // fully clamped: mass only
        return lowest >= first && lowest < last;
    };
    std::vector<PetscInt> idx;
    auto insert = [&](Term term, const std::vector<int>& element_dofs, const Eigen::MatrixXd& A) {
        idx.assign(element_dofs.begin(), element_dofs.end());
        const PetscInt n = static_cast<PetscInt>(idx.size());
        // MatSetValues reads row-major, Eigen stores column-major: the same
        // for the symmetric terms; a skew-symmetric (gyroscopic) one is copied
        // transposed.
        COREMODAL_ASSERT(A.rows() == n && A.cols() == n);
        const Eigen::MatrixXd row_major_if_skew = term == Term::gyroscopic ? Eigen::MatrixXd(A.transpose()) : A;
        COREMODAL_PETSC(MatSetValues(system[term], n, idx.data(), n, idx.data(), row_major_if_skew.data(), ADD_VALUES));
    };
    double local_mass = assemble_cells(
        mesh, materials, dofs, [&](int c) { return owned_here(mesh.cell(c), mesh.nodes_per_cell()); }, insert,
        extra_terms);
    local_mass += assemble_couplings(
        couplings, dofs, [&](const std::vector<int>& nodes) { return owned_here(nodes.data(), static_cast<int>(nodes.size())); },
        insert, terms);
    for (Term t : terms) {
        Mat A = system[t];
        COREMODAL_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
        COREMODAL_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
        if (t == Term::gyroscopic) continue;  // skew-symmetric
        COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
        COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    }
    MPI_Allreduce(&local_mass, &system.model_mass, 1, MPI_DOUBLE, MPI_SUM, comm);
    return system;
}

}  // namespace coremodal
