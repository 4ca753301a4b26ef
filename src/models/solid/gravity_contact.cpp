#include "models/solid/gravity_contact.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "eigensolve/modal_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "modes/mode_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

const OneSidedContact& contact_of(const SupportEffects& effects, const ContactFace& f) {
    return *effects.chucks.at(f.chuck).one_sided;
}

// The consistent weight M a, a = -g e_y on every free node.
PetscVector gravity_load(const OperatorSet& base, const DofMap& dofs, double g) {
    PetscVector a, F;
    COREMODAL_PETSC(MatCreateVecs(base.M(), a.out(), F.out()));
    PetscInt lo = 0, hi = 0;
    COREMODAL_PETSC(VecGetOwnershipRange(a, &lo, &hi));
    COREMODAL_PETSC(VecSet(a, 0.0));
    for (int n = 0; n < static_cast<int>(dofs.node_first_dof.size()); ++n)
        if (const PetscInt d = dofs.dof(n, 1); d >= lo && d < hi) COREMODAL_PETSC(VecSetValue(a, d, -g, INSERT_VALUES));
    COREMODAL_PETSC(VecAssemblyBegin(a));
    COREMODAL_PETSC(VecAssemblyEnd(a));
    COREMODAL_PETSC(MatMult(base.M(), a, F));
    return F;
}

std::vector<PetscInt> coupling_dofs(const std::vector<int>& nodes, const DofMap& dofs) {
    std::vector<PetscInt> idx;
    for (int n : nodes)
        for (int c = 0; c < 3; ++c) idx.push_back(dofs.dof(n, c));
    return idx;
}

// K_work = K_base + the iterate's springs; rhs = F_g + the iterate's loads.
// Rank 0 inserts every face (PETSc's stash sends off-rank rows).
void linearise(const std::vector<ContactFace>& faces, const ContactIterate& it, const SupportEffects& effects,
               const DofMap& dofs, Mat K_work, Vec rhs) {
    std::vector<CouplingElement> springs;
    size_t k = 0;
    for (const ContactFace& f : faces) {
        const OneSidedContact& c = contact_of(effects, f);
        const size_t first = k;
        springs.push_back(contact_coupling(f, [&](size_t q) -> Eigen::Matrix3d {
            // diag(k, eps k, eps k) in (r, theta, z), turned to (x, y, z)
            const Eigen::Vector3d kc = static_contact_stiffness(c, it, first + q);
            const Eigen::Vector3d e = f.points[q].normal();
            return kc[1] * Eigen::Matrix3d::Identity() + (kc[0] - kc[1]) * e * e.transpose();
        }));
        if (mpi_rank() == 0) {
            const Eigen::VectorXd load =
                contact_load(f, [&](size_t q) { return static_contact_traction(c, it, first + q); });
            const std::vector<PetscInt> idx = coupling_dofs(springs.back().nodes, dofs);
            COREMODAL_PETSC(VecSetValues(rhs, static_cast<PetscInt>(idx.size()), idx.data(), load.data(), ADD_VALUES));
        }
        k += f.points.size();
    }
    COREMODAL_PETSC(VecAssemblyBegin(rhs));
    COREMODAL_PETSC(VecAssemblyEnd(rhs));
    add_couplings_to(K_work, springs, dofs);
}

// One Newton step: the interpenetration at every point after solving with
// the iterate's linearisation.
std::vector<double> newton_step(KSP ksp, Mat K_base, Mat K_work, Vec F_g, const std::vector<ContactFace>& faces,
                                const ContactIterate& it, const SupportEffects& effects, const DofMap& dofs) {
    COREMODAL_PETSC(MatCopy(K_base, K_work, SAME_NONZERO_PATTERN));
    PetscVector rhs, u;
    COREMODAL_PETSC(VecDuplicate(F_g, rhs.out()));
    COREMODAL_PETSC(VecDuplicate(F_g, u.out()));
    COREMODAL_PETSC(VecCopy(F_g, rhs));
    linearise(faces, it, effects, dofs, K_work, rhs);
    COREMODAL_PETSC(KSPSetOperators(ksp, K_work, K_work));
    COREMODAL_PETSC(KSPSolve(ksp, rhs, u));
    KSPConvergedReason reason;
    COREMODAL_PETSC(KSPGetConvergedReason(ksp, &reason));
    if (reason < 0)
        throw SolveError("the static solve under gravity failed (Cholesky factor, reason " + std::to_string(reason) +
                         "): the roll is not held while its contact is open; check the clearance and the bearings");
    const std::vector<double> values = gather_to_all(u);
    const NodeDisplacement at = [&](int node) {
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        for (int c = 0; c < 3; ++c)
            if (const int d = dofs.dof(node, c); d >= 0) x[c] = values[d];
        return x;
    };
    std::vector<double> d;
    for (const ContactFace& f : faces)
        for (const ContactPoint& q : f.points) d.push_back(interpenetration(f, q, contact_of(effects, f).clearance, at));
    return d;
}

// The solid's contact points, face-major, as the active-set iteration sees them.
std::vector<BorePoint> bore_points(const std::vector<ContactFace>& faces) {
    std::vector<BorePoint> out;
    for (const ContactFace& f : faces)
        for (const ContactPoint& q : f.points) out.push_back({f.chuck, q.x, q.area_weight});
    return out;
}

}  // namespace

void add_couplings_to(Mat K, const std::vector<CouplingElement>& couplings, const DofMap& dofs) {
    if (mpi_rank() == 0)
        for (const CouplingElement& e : couplings) {
            const std::vector<PetscInt> idx = coupling_dofs(e.nodes, dofs);
            const PetscInt n = static_cast<PetscInt>(idx.size());
            // Symmetric: Eigen's column-major data reads the same row-major.
            COREMODAL_PETSC(MatSetValues(K, n, idx.data(), n, idx.data(), e.matrix(Term::stiffness).data(), ADD_VALUES));
        }
    COREMODAL_PETSC(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
}

GravityContact solve_gravity_contact(const OperatorSet& base, const DofMap& dofs, const ChuckSupports& supports,
                                     const SupportEffects& effects, const Printer& say) {
    COREMODAL_ASSERT(effects.gravity && !supports.contact_faces.empty());
    const std::vector<ContactFace>& faces = supports.contact_faces;
    const PetscVector F_g = gravity_load(base, dofs, effects.gravity->g);
    PetscMatrix K_work;
    COREMODAL_PETSC(MatDuplicate(base.K(), MAT_COPY_VALUES, K_work.out()));
    COREMODAL_PETSC(MatSetOption(K_work, MAT_SYMMETRIC, PETSC_TRUE));
    COREMODAL_PETSC(MatSetOption(K_work, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    // -static_pc_factor_mat_solver_type mumps chooses another factor.
    const PetscKsp ksp = direct_cholesky_solver(PetscObjectComm(reinterpret_cast<PetscObject>(K_work.get())), "static_");
    return solve_active_set(
        bore_points(faces), effects,
        [&](const ContactIterate& it) { return newton_step(ksp, base.K(), K_work, F_g, faces, it, effects, dofs); },
        say);
}

}  // namespace coremodal
