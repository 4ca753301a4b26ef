#include "modes/mode_shapes.hpp"

namespace coremodal {

namespace {

// x gathered into one sequential vector, on rank 0 or on every rank.
std::vector<double> gather(Vec x, bool to_all) {
    PetscScatter scatter;
    PetscVector x0;
    COREMODAL_PETSC(to_all ? VecScatterCreateToAll(x, scatter.out(), x0.out())
                           : VecScatterCreateToZero(x, scatter.out(), x0.out()));
    COREMODAL_PETSC(VecScatterBegin(scatter, x, x0, INSERT_VALUES, SCATTER_FORWARD));
    COREMODAL_PETSC(VecScatterEnd(scatter, x, x0, INSERT_VALUES, SCATTER_FORWARD));
    std::vector<double> values;
    if (!to_all && mpi_rank(PetscObjectComm((PetscObject)x)) != 0) return values;
    PetscInt size;
    COREMODAL_PETSC(VecGetSize(x0, &size));
    const PetscScalar* v;
    COREMODAL_PETSC(VecGetArrayRead(x0, &v));
    values.assign(v, v + size);
    COREMODAL_PETSC(VecRestoreArrayRead(x0, &v));
    return values;
}

}  // namespace

std::vector<double> gather_to_root(Vec x) { return gather(x, false); }

std::vector<double> gather_to_all(Vec x) { return gather(x, true); }

std::vector<double> gather_node_displacements(Vec x, const Mesh& mesh, const DofMap& dofs) {
    const std::vector<double> values = gather_to_root(x);
    std::vector<double> u;
    if (mpi_rank(PetscObjectComm((PetscObject)x)) != 0) return u;
    u.assign(3 * static_cast<size_t>(mesh.n_nodes()), 0.0);
    for (int n = 0; n < mesh.n_nodes(); ++n)
        if (dofs.node_first_dof[n] >= 0)
            for (int c = 0; c < 3; ++c) u[3 * n + c] = values[dofs.node_first_dof[n] + c];
    return u;
}

EffectiveMassCalculator::EffectiveMassCalculator(Mat M, const Mesh& mesh, const DofMap& dofs) {
    PetscInt lo, hi;
    for (int d = 0; d < 4; ++d) {
        PetscVector r;
        COREMODAL_PETSC(MatCreateVecs(M, r.out(), M_r_[d].out()));
        COREMODAL_PETSC(VecGetOwnershipRange(r, &lo, &hi));
        PetscScalar* v;
        COREMODAL_PETSC(VecGetArray(r, &v));
        for (int n = 0; n < mesh.n_nodes(); ++n) {
            const int first = dofs.node_first_dof[n];
            if (first < lo || first >= hi) continue;
            const auto& x = mesh.nodes[n];
            const double rigid[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-x[1], x[0], 0}};
            for (int c = 0; c < 3; ++c) v[first - lo + c] = rigid[d][c];
        }
        COREMODAL_PETSC(VecRestoreArray(r, &v));
        COREMODAL_PETSC(MatMult(M, r, M_r_[d]));
    }
}

EffectiveMass EffectiveMassCalculator::operator()(Vec x) const {
    PetscScalar g[4];
    for (int d = 0; d < 4; ++d) COREMODAL_PETSC(VecDot(x, M_r_[d], &g[d]));
    return {g[0] * g[0], g[1] * g[1], g[2] * g[2], g[3] * g[3]};
}

}  // namespace coremodal
