#include "assembly/petsc_system.hpp"

#include "common/error.hpp"

#include <algorithm>

namespace coremodal {
namespace {

// Node -> cells incidence in compressed rows.
struct NodeCells {
    std::vector<int> offset, cells;
};

NodeCells node_cells(const Mesh& mesh) {
    const int npc = mesh.nodes_per_cell();
    NodeCells nc;
    nc.offset.assign(mesh.n_nodes() + 1, 0);
    for (int v : mesh.cells) ++nc.offset[v + 1];
    for (int n = 0; n < mesh.n_nodes(); ++n) nc.offset[n + 1] += nc.offset[n];
    nc.cells.resize(mesh.cells.size());
    std::vector<int> fill(nc.offset.begin(), nc.offset.end() - 1);
    for (int c = 0; c < mesh.n_cells(); ++c)
        for (int a = 0; a < npc; ++a) nc.cells[fill[mesh.cell(c)[a]]++] = c;
    return nc;
}

// Number of free neighbour nodes (including itself) of each owned free node,
// split into those owned here (diagonal block) and elsewhere (off-diagonal).
void count_block_nonzeros(const Mesh& mesh, const DofMap& dofs, int first, int last,
                          std::vector<PetscInt>& d_nnz, std::vector<PetscInt>& o_nnz) {
    const NodeCells nc = node_cells(mesh);
    const int npc = mesh.nodes_per_cell();
    std::vector<int> free_node_of(mesh.n_nodes());
    for (int n = 0; n < mesh.n_nodes(); ++n) free_node_of[n] = dofs.node_first_dof[n] < 0 ? -1 : dofs.node_first_dof[n] / 3;
    d_nnz.assign(last - first, 0);
    o_nnz.assign(last - first, 0);
    std::vector<int> seen(mesh.n_nodes(), -1);
    for (int n = 0; n < mesh.n_nodes(); ++n) {
        const int row = free_node_of[n];
        if (row < first || row >= last) continue;
        for (int k = nc.offset[n]; k < nc.offset[n + 1]; ++k) {
            const int* nodes = mesh.cell(nc.cells[k]);
            for (int a = 0; a < npc; ++a) {
                const int col = free_node_of[nodes[a]];
                if (col < 0 || seen[nodes[a]] == n) continue;
                seen[nodes[a]] = n;
                ++((col >= first && col < last) ? d_nnz : o_nnz)[row - first];
            }
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

PetscSystem assemble_petsc(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                           MPI_Comm comm) {
    const int rank = mpi_rank(comm), size = mpi_size(comm);
    const auto [first, last] = owned_free_nodes(dofs.n_free_nodes, rank, size);
    std::vector<PetscInt> d_nnz, o_nnz;
    count_block_nonzeros(mesh, dofs, first, last, d_nnz, o_nnz);

    PetscSystem system;
    system.K = create_matrix(comm, 3 * (last - first), d_nnz, o_nnz);
    system.M = create_matrix(comm, 3 * (last - first), d_nnz, o_nnz);

    // A cell is assembled by the rank owning its lowest-numbered free node.
    auto take = [&](int c) {
        int lowest = dofs.n_free_nodes;
        for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
            const int d = dofs.node_first_dof[mesh.cell(c)[a]];
            if (d >= 0) lowest = std::min(lowest, d / 3);
        }
        if (lowest == dofs.n_free_nodes) return rank == 0;  // fully clamped: mass only
        return lowest >= first && lowest < last;
    };
    std::vector<PetscInt> idx;
    auto insert = [&](const std::vector<int>& cell_dofs, const Eigen::MatrixXd& Kc, const Eigen::MatrixXd& Mc) {
        idx.assign(cell_dofs.begin(), cell_dofs.end());
        const PetscInt n = static_cast<PetscInt>(idx.size());
        // Element matrices are symmetric, so Eigen's column-major storage
        // equals the row-major layout MatSetValues expects.
        COREMODAL_PETSC(MatSetValues(system.K, n, idx.data(), n, idx.data(), Kc.data(), ADD_VALUES));
        COREMODAL_PETSC(MatSetValues(system.M, n, idx.data(), n, idx.data(), Mc.data(), ADD_VALUES));
    };
    const double local_mass = assemble_cells(mesh, materials, dofs, take, insert);
    for (Mat A : {system.K.get(), system.M.get()}) {
        COREMODAL_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
        COREMODAL_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
        COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
        COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    }
    MPI_Allreduce(&local_mass, &system.model_mass, 1, MPI_DOUBLE, MPI_SUM, comm);
    return system;
}

}  // namespace coremodal
