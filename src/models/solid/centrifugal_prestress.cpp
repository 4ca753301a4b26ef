#include "models/solid/centrifugal_prestress.hpp"

#include "common/error.hpp"
#include "eigensolve/modal_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "modes/mode_shapes.hpp"

#include <petscksp.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace coremodal {
namespace {


// A rigid motion is free when |K r| / (max diag K |r|) is below this: round-off
// of the assembly (measured ~1e-16 on free tubes) against at least ~1e-6 for
// a motion the supports hold (a spring or a clamp acts on a whole face).
constexpr double kFreeRigidMotion = 1e-10;

const std::array<const char*, 6> kRigidNames = {"translation x", "translation y", "translation z",
                                                "rotation about x", "rotation about y", "rotation about z"};

// The rigid motion k (0-2 translations, 3-5 rotations) at a point.
Eigen::Vector3d rigid_motion(int k, const Eigen::Vector3d& x) {
    Eigen::Vector3d axis = Eigen::Vector3d::Unit(k % 3);
    return k < 3 ? axis : Eigen::Vector3d(axis.cross(x));
}

PetscVector rigid_field(Mat K, const Mesh& mesh, const DofMap& dofs, int k) {
    PetscVector r;
    COREMODAL_PETSC(MatCreateVecs(K, r.out(), nullptr));
    COREMODAL_PETSC(VecSet(r, 0.0));
    if (mpi_rank() == 0)
        for (int n = 0; n < mesh.n_nodes(); ++n) {
            if (dofs.node_first_dof[n] < 0) continue;
            const auto& p = mesh.nodes[n];
            const Eigen::Vector3d v = rigid_motion(k, Eigen::Vector3d(p[0], p[1], p[2]));
            for (int c = 0; c < 3; ++c) COREMODAL_PETSC(VecSetValue(r, dofs.dof(n, c), v[c], INSERT_VALUES));
        }
    COREMODAL_PETSC(VecAssemblyBegin(r));
    COREMODAL_PETSC(VecAssemblyEnd(r));
    return r;
}

double max_diagonal(Mat K) {
    PetscVector d;
    COREMODAL_PETSC(MatCreateVecs(K, d.out(), nullptr));
    COREMODAL_PETSC(MatGetDiagonal(K, d));
    PetscReal m = 0;
    COREMODAL_PETSC(VecNorm(d, NORM_INFINITY, &m));
    return m;
}

bool leaves_free(Mat K, Vec r, double k_scale) {
    PetscVector Kr;
    COREMODAL_PETSC(VecDuplicate(r, Kr.out()));
    COREMODAL_PETSC(MatMult(K, r, Kr));
    return vector_norm(Kr) <= kFreeRigidMotion * k_scale * vector_norm(r);
}

// One DOF per free rigid motion such that the motions' values there form a
// nonsingular matrix: Gaussian elimination with the largest entry as pivot.
std::vector<PetscInt> pinned_dofs(std::vector<std::vector<double>> fields) {
    std::vector<PetscInt> pins;
    for (size_t i = 0; i < fields.size(); ++i) {
        const std::vector<double>& f = fields[i];
        const auto j = std::max_element(f.begin(), f.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) - f.begin();
        pins.push_back(static_cast<PetscInt>(j));
        for (size_t l = i + 1; l < fields.size(); ++l) {
            const double ratio = fields[l][j] / f[j];
            for (size_t d = 0; d < f.size(); ++d) fields[l][d] -= ratio * f[d];
        }
    }
    return pins;
}

PetscVector centrifugal_load(Mat K, const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs) {
    PetscVector f;
    COREMODAL_PETSC(MatCreateVecs(K, f.out(), nullptr));
    COREMODAL_PETSC(VecSet(f, 0.0));
    // The -1 of eliminated DOFs must be skipped: unlike MatSetValues, a
    // vector writes before its array unless told to ignore them.
    COREMODAL_PETSC(VecSetOption(f, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE));
    if (mpi_rank() == 0)  // PETSc's stash sends off-rank entries
        assemble_centrifugal_load(mesh, materials, dofs, [](int) { return true; },
                                  [&](const std::vector<int>& idx, const Eigen::VectorXd& v) {
                                      const std::vector<PetscInt> i(idx.begin(), idx.end());
                                      COREMODAL_PETSC(VecSetValues(f, static_cast<PetscInt>(i.size()), i.data(),
                                                                   v.data(), ADD_VALUES));
                                  });
    COREMODAL_PETSC(VecAssemblyBegin(f));
    COREMODAL_PETSC(VecAssemblyEnd(f));
    return f;
}

// The node displacements (3 per mesh node) of a DOF vector on every rank.
std::vector<double> node_values(Vec u, const Mesh& mesh, const DofMap& dofs) {
    const std::vector<double> values = gather_to_all(u);
    std::vector<double> out(3 * static_cast<size_t>(mesh.n_nodes()), 0.0);
    for (int n = 0; n < mesh.n_nodes(); ++n)
        for (int c = 0; c < 3; ++c)
            if (const int d = dofs.dof(n, c); d >= 0) out[3 * n + c] = values[d];
    return out;
}

NodeField field_of(const CentrifugalState& state) {
    return [&state](int n) { return Eigen::Vector3d(state.node_displacement.data() + 3 * n); };
}

}  // namespace

CentrifugalState solve_centrifugal_state(const OperatorSet& operators, const Mesh& mesh,
                                         const std::vector<PartMaterial>& materials, const DofMap& dofs) {
    COREMODAL_ASSERT(mpi_size() == 1);  // the pins' choice reads whole vectors
    Mat K = operators.K();
    CentrifugalState state;
    PetscVector f = centrifugal_load(K, mesh, materials, dofs);
    const double k_scale = max_diagonal(K), f_norm = vector_norm(f);
    std::vector<std::vector<double>> free_fields;
    for (int k = 0; k < 6; ++k) {
        PetscVector r = rigid_field(K, mesh, dofs, k);
        if (!leaves_free(K, r, k_scale)) continue;
        state.pinned.push_back(kRigidNames[k]);
        PetscScalar work = 0;
        COREMODAL_PETSC(VecDot(r, f, &work));
        state.load_work_on_pinned = std::max(state.load_work_on_pinned, std::abs(work) / (vector_norm(r) * f_norm));
        free_fields.push_back(gather_to_all(r));
    }
    PetscMatrix K_pinned;
    COREMODAL_PETSC(MatDuplicate(K, MAT_COPY_VALUES, K_pinned.out()));
    const std::vector<PetscInt> pins = pinned_dofs(free_fields);
    // The pinned rows and columns become k_scale on the diagonal (not 1: a
    // pivot of the matrix's own size), their right-hand side zero.
    COREMODAL_PETSC(MatZeroRowsColumns(K_pinned, static_cast<PetscInt>(pins.size()), pins.data(), k_scale, nullptr, nullptr));
    for (PetscInt p : pins) COREMODAL_PETSC(VecSetValue(f, p, 0.0, INSERT_VALUES));
    COREMODAL_PETSC(VecAssemblyBegin(f));
    COREMODAL_PETSC(VecAssemblyEnd(f));
    COREMODAL_PETSC(MatSetOption(K_pinned, MAT_SYMMETRIC, PETSC_TRUE));
    // -centrifugal_pc_factor_mat_solver_type mumps chooses another factor.
    const PetscKsp ksp = direct_cholesky_solver(PetscObjectComm(reinterpret_cast<PetscObject>(K_pinned.get())), "centrifugal_");
    COREMODAL_PETSC(KSPSetOperators(ksp, K_pinned, K_pinned));
    PetscVector u;
    COREMODAL_PETSC(VecDuplicate(f, u.out()));
    COREMODAL_PETSC(KSPSolve(ksp, f, u));
    KSPConvergedReason reason;
    COREMODAL_PETSC(KSPGetConvergedReason(ksp, &reason));
    if (reason < 0)
        throw SolveError("the static solve under the centrifugal load failed (Cholesky factor, reason " +
                         std::to_string(reason) + "): a part is held by nothing the rigid motions of the whole "
                         "account for; check the supports");
    state.node_displacement = node_values(u, mesh, dofs);
    return state;
}

void add_centrifugal_term(OperatorSet& operators, const Mesh& mesh, const std::vector<PartMaterial>& materials,
                          const DofMap& dofs, const CentrifugalState& state, CentrifugalPart part) {
    PetscMatrix K_omega;
    COREMODAL_PETSC(MatDuplicate(operators.K(), MAT_DO_NOT_COPY_VALUES, K_omega.out()));
    COREMODAL_PETSC(MatZeroEntries(K_omega));
    if (mpi_rank() == 0) {
        std::vector<PetscInt> idx;
        assemble_centrifugal_cells(mesh, materials, dofs, [](int) { return true; }, field_of(state), part,
                                   [&](Term, const std::vector<int>& cell_dofs, const Eigen::MatrixXd& A) {
                                       idx.assign(cell_dofs.begin(), cell_dofs.end());
                                       const PetscInt n = static_cast<PetscInt>(idx.size());
                                       // symmetric: Eigen's column-major reads the same row-major
                                       COREMODAL_PETSC(MatSetValues(K_omega, n, idx.data(), n, idx.data(), A.data(),
                                                                    ADD_VALUES));
                                   });
    }
    COREMODAL_PETSC(MatAssemblyBegin(K_omega, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(K_omega, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatSetOption(K_omega, MAT_SYMMETRIC, PETSC_TRUE));
    COREMODAL_PETSC(MatSetOption(K_omega, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    operators.matrices[Term::centrifugal] = std::move(K_omega);
}

std::vector<PointStress> centrifugal_stresses(const Mesh& mesh, const std::vector<PartMaterial>& materials,
                                              const CentrifugalState& state) {
    std::vector<PointStress> out;
    const int npc = mesh.nodes_per_cell();
    CellCoords coords(npc, 3);
    Eigen::VectorXd u(3 * npc);
    for (int c = 0; c < mesh.n_cells(); ++c) {
        for (int a = 0; a < npc; ++a) {
            const int n = mesh.cell(c)[a];
            for (int d = 0; d < 3; ++d) coords(a, d) = mesh.nodes[n][d];
            u.segment<3>(3 * a) = Eigen::Vector3d(state.node_displacement.data() + 3 * n);
        }
        const auto s = element_stresses(mesh.cell_type, coords, materials.at(mesh.cell_part[c]).C_cylindrical, u);
        out.insert(out.end(), s.begin(), s.end());
    }
    return out;
}

}  // namespace coremodal
