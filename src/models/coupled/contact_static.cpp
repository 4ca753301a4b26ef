#include "models/coupled/contact_static.hpp"

#include "common/error.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "modes/mode_shapes.hpp"

#include <algorithm>

namespace coremodal {

bool mirror_even(HarmonicFamily h) { return h.n == 0 || (h.n % 2 == 0) == (h.family == Family::cos); }

namespace {

// The blocks of `all` that `keep` accepts, renumbered from offset 0.
CoupledDofs select_blocks(const CoupledDofs& all, bool (*keep)(HarmonicFamily)) {
    CoupledDofs out;
    out.n_max = all.n_max;
    for (CoupledBlock block : all.blocks) {
        if (!keep(block.harmonic)) continue;
        block.offset = out.n_dofs;
        out.n_dofs += block.dofs.n_dofs;
        out.blocks.push_back(std::move(block));
    }
    return out;
}

const OneSidedContact& contact_of(const SupportEffects& effects, const HarmonicContactPoint& p) {
    return *effects.chucks.at(p.bore.chuck).one_sided;
}

// The core's and the chuck's DOF of component c of edge node a in a block (-1: held).
struct EdgeDofs {
    int core, chuck;
};
EdgeDofs edge_dofs(const SectionMesh& mesh, const SupportEffects& effects, const HarmonicContactPoint& p,
                   const CoupledBlock& block, int a, int c) {
    const std::string& chuck = effects.chucks[p.bore.chuck].placement.chuck;
    const auto dof = [&](const std::string& side) {
        const int d = block.dofs.of_component[3 * mesh.edge_groups.at("interface_" + chuck + side)[p.edge][a] + c];
        return d < 0 ? -1 : d + block.offset;
    };
    return {dof("_core"), dof("_chuck")};
}

// The consistent weight -g M r_y, r_y the y translation in block (1, sin).
PetscVector gravity_load(const CoupledDofs& dofs, const SectionMesh& section, Mat M, double g) {
    PetscVector a, F;
    COREMODAL_PETSC(MatCreateVecs(M, a.out(), F.out()));
    COREMODAL_PETSC(VecSet(a, 0.0));
    const int b = dofs.block_of(1, Family::sin);
    COREMODAL_ASSERT(b >= 0);
    if (mpi_rank() == 0) {
        const CoupledBlock& block = dofs.blocks[b];
        const std::vector<double> r = harmonic_rigid_field(section, block.dofs, 1, RigidMotion::x);
        for (int i = 0; i < block.dofs.n_dofs; ++i)
            if (r[i] != 0) COREMODAL_PETSC(VecSetValue(a, block.offset + i, -g * r[i], INSERT_VALUES));
    }
    COREMODAL_PETSC(VecAssemblyBegin(a));
    COREMODAL_PETSC(VecAssemblyEnd(a));
    COREMODAL_PETSC(MatMult(M, a, F));
    return F;
}

// The iterate's constant tractions as loads on the coupled DOFs: + on the core, - on the chuck.
void add_contact_loads(const SectionMesh& mesh, const SupportEffects& effects, const ContactLayer& layer,
                       const ContactIterate& it, const CoupledDofs& dofs, Vec rhs) {
    if (mpi_rank() == 0)
        for (size_t i = 0; i < layer.points.size(); ++i) {
            const HarmonicContactPoint& p = layer.points[i];
            const double t = static_contact_traction(contact_of(effects, p), it, i);
            if (t == 0) continue;
            for (const CoupledBlock& block : dofs.blocks) {
                const double f = t * p.bore.area_weight * trig_factor(block.harmonic, 0, p.theta);
                for (int a = 0; a < 3; ++a) {
                    const EdgeDofs d = edge_dofs(mesh, effects, p, block, a, 0);
                    if (d.core >= 0) COREMODAL_PETSC(VecSetValue(rhs, d.core, f * p.N[a], ADD_VALUES));
                    if (d.chuck >= 0) COREMODAL_PETSC(VecSetValue(rhs, d.chuck, -f * p.N[a], ADD_VALUES));
                }
            }
        }
    COREMODAL_PETSC(VecAssemblyBegin(rhs));
    COREMODAL_PETSC(VecAssemblyEnd(rhs));
}

// d = -c - du_r at every point, from the coupled displacement u (every DOF).
std::vector<double> interpenetrations(const SectionMesh& mesh, const SupportEffects& effects,
                                      const ContactLayer& layer, const CoupledDofs& dofs, const std::vector<double>& u) {
    std::vector<double> d;
    for (const HarmonicContactPoint& p : layer.points) {
        double du = 0;
        for (const CoupledBlock& block : dofs.blocks) {
            double value = 0;
            for (int a = 0; a < 3; ++a) {
                const EdgeDofs e = edge_dofs(mesh, effects, p, block, a, 0);
                value += p.N[a] * ((e.core >= 0 ? u[e.core] : 0.0) - (e.chuck >= 0 ? u[e.chuck] : 0.0));
            }
            du += trig_factor(block.harmonic, 0, p.theta) * value;
        }
        d.push_back(-contact_of(effects, p).clearance - du);
    }
    return d;
}

}  // namespace

CoupledContactState solve_coupled_contact(const Scene& scene, const SectionMesh& section,
                                          const std::vector<PartMaterial>& materials, int n_max, const Printer& say) {
    const SupportEffects effects = support_effects(scene);
    COREMODAL_ASSERT(effects.gravity);
    const CoupledDofs dofs = select_blocks(coupled_dofs(scene, section, n_max), mirror_even);
    Attachments attached = attachments(scene);
    ContactLayer layer;
    layer.points = contact_points(scene, section);
    layer.set_stiffness(std::vector<Eigen::Vector3d>(layer.points.size(), Eigen::Vector3d::Zero()));
    attached.contact = layer;
    const PetscVector F_g =
        gravity_load(dofs, section, assemble_coupled(scene, section, materials, dofs, attached).operators.M(),
                     effects.gravity->g);
    // -static_pc_factor_mat_solver_type mumps chooses another factor.
    const PetscKsp ksp = direct_cholesky_solver(PETSC_COMM_WORLD, "static_");
    std::vector<BorePoint> points;
    for (const HarmonicContactPoint& p : layer.points) points.push_back(p.bore);
    const auto newton_step = [&](const ContactIterate& it) {
        std::vector<Eigen::Vector3d> k;
        for (size_t i = 0; i < layer.points.size(); ++i)
            k.push_back(static_contact_stiffness(contact_of(effects, layer.points[i]), it, i));
        attached.contact->set_stiffness(std::move(k));
        const CoupledSystem system = assemble_coupled(scene, section, materials, dofs, attached);
        PetscVector rhs, u;
        COREMODAL_PETSC(VecDuplicate(F_g, rhs.out()));
        COREMODAL_PETSC(VecDuplicate(F_g, u.out()));
        COREMODAL_PETSC(VecCopy(F_g, rhs));
        add_contact_loads(section, effects, *attached.contact, it, dofs, rhs);
        COREMODAL_PETSC(KSPSetOperators(ksp, system.operators.K(), system.operators.K()));
        COREMODAL_PETSC(KSPSolve(ksp, rhs, u));
        KSPConvergedReason reason;
        COREMODAL_PETSC(KSPGetConvergedReason(ksp, &reason));
        if (reason < 0)
            throw SolveError("the coupled harmonics' static solve under gravity failed (Cholesky factor, reason " +
                             std::to_string(reason) +
                             "): the roll is not held while its contact is open; check the clearance and the bearings");
        return interpenetrations(section, effects, layer, dofs, gather_to_all(u));
    };
    CoupledContactState out;
    out.contact = solve_active_set(points, effects, newton_step, say);
    std::vector<Eigen::Vector3d> k;
    for (size_t i = 0; i < layer.points.size(); ++i) {
        const ContactPointState& s = out.contact.state[i];
        k.push_back(s.closed() ? contact_of(effects, layer.points[i]).linearised(s.p).per_area_cylindrical()
                               : Eigen::Vector3d::Zero());
    }
    out.layer = std::move(layer);
    out.layer.set_stiffness(std::move(k));
    return out;
}

}  // namespace coremodal
