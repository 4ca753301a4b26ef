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


// In the static solve the contact is frictionless: a symmetric roll's
// weight is carried by normal pressure, and friction would only resist the
// slip while the clearance closes. A tangential spring of this fraction of
// k_n at closed points removes the two motions nothing else holds (the roll
// turning about its axis and sliding along it, which the weight does not
// load); it carries about 1e-6 of the load.
constexpr double kStaticTangentialFraction = 1e-6;
// The active set of a compliant contact settles in a few iterations; a set
// that keeps changing after this many is cycling.
constexpr int kMaxContactIterations = 60;
// Newton on an exponential law overshoots from a point closed at low
// pressure: no point may close further than this many u0 per step (the
// pressure rises at most e^3 = 20 times), the step is scaled down otherwise.
constexpr double kMaxClosingStep = 3.0;
// The first iterate closes the bore's top (within this angle of +y) at zero
// pressure. A wider start would overshoot: a spring linearised at d = 0
// pulls its point across the whole clearance, so closing the upper half
// would drop the core by 4c/pi and start the exponential law at d = 0.27 c
// (7 u0 at the defaults), far from the state.
constexpr double kFirstArc = 10 * M_PI / 180;
// Converged when the set repeats and no point moves by more than this
// fraction of u0 (20 um by default: 2e-13 m) in a full Newton step.
constexpr double kConvergedStep = 1e-8;

// The linearisation of one iteration: which points carry springs, and the
// (d, p) each is linearised about.
struct Iterate {
    std::vector<char> active;
    std::vector<double> d, p;
};

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
void linearise(const std::vector<ContactFace>& faces, const Iterate& it, const SupportEffects& effects,
               const DofMap& dofs, Mat K_work, Vec rhs) {
    std::vector<CouplingElement> springs;
    size_t k = 0;
    for (const ContactFace& f : faces) {
        const OneSidedContact& c = contact_of(effects, f);
        const size_t first = k;
        const auto stiffness = [&](size_t q) { return c.law.stiffness(it.p[first + q]); };
        springs.push_back(contact_coupling(f, [&](size_t q) -> Eigen::Matrix3d {
            if (!it.active[first + q]) return Eigen::Matrix3d::Zero();
            const Eigen::Vector3d e = f.points[q].normal();
            return stiffness(q) * (kStaticTangentialFraction * Eigen::Matrix3d::Identity() +
                                   (1 - kStaticTangentialFraction) * e * e.transpose());
        }));
        if (mpi_rank() == 0) {
            const Eigen::VectorXd load = contact_load(f, [&](size_t q) {
                const size_t i = first + q;
                return it.active[i] ? it.p[i] - stiffness(q) * (it.d[i] + c.clearance) : 0.0;
            });
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
                                const Iterate& it, const SupportEffects& effects, const DofMap& dofs) {
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

Iterate first_iterate(const std::vector<ContactFace>& faces) {
    Iterate it;
    for (const ContactFace& f : faces)
        for (const ContactPoint& q : f.points) {
            it.active.push_back(q.normal()[1] > std::cos(kFirstArc));
            it.d.push_back(0);
            it.p.push_back(0);
        }
    return it;
}

// The next iterate from the step's interpenetrations: damped so that no
// point closes by more than kMaxClosingStep u0 (not on the first step, whose
// iterate is a guess, not a state). Returns the full step's largest move, in u0.
double advance(Iterate& it, const std::vector<double>& d_new, const std::vector<ContactFace>& faces,
               const SupportEffects& effects, bool first, double& alpha) {
    std::vector<double> u0;
    for (const ContactFace& f : faces) u0.insert(u0.end(), f.points.size(), contact_of(effects, f).law.u0());
    double closing = 0, moved = 0;
    for (size_t i = 0; i < d_new.size(); ++i) {
        closing = std::max(closing, (std::max(d_new[i], 0.0) - std::max(it.d[i], 0.0)) / u0[i]);
        moved = std::max(moved, std::abs(d_new[i] - it.d[i]) / u0[i]);
    }
    alpha = first || closing <= kMaxClosingStep ? 1.0 : kMaxClosingStep / closing;
    size_t k = 0;
    for (const ContactFace& f : faces) {
        const StackContact& law = contact_of(effects, f).law;
        for (size_t q = 0; q < f.points.size(); ++q, ++k) {
            it.d[k] = first ? d_new[k] : it.d[k] + alpha * (d_new[k] - it.d[k]);
            it.active[k] = it.d[k] > 0;
            it.p[k] = law.pressure(it.d[k]);
        }
    }
    return moved;
}

// The rigid-motion stiffnesses of the closed contact (ChuckContactState).
void add_support_stiffness(const std::vector<ContactFace>& faces, const std::vector<ContactPointState>& s,
                           const SupportEffects& effects, std::vector<ChuckContactState>& out) {
    size_t k = 0;
    for (const ContactFace& f : faces)
        for (const ContactPoint& q : f.points) {
            const ContactPointState& p = s[k++];
            if (!p.closed()) continue;
            ChuckContactState& c = out[f.chuck];
            const Eigen::Matrix3d D = contact_of(effects, f).linearised(p.p).per_area(std::atan2(q.x[1], q.x[0]));
            const double z_mid = (c.z_from_m + c.z_to_m) / 2;
            const Eigen::Vector3d tilt(0, -(q.x[2] - z_mid), q.x[1]);  // e_x x (x - x_mid)
            c.vertical_stiffness_n_per_m += q.area_weight * D(1, 1);
            c.horizontal_stiffness_n_per_m += q.area_weight * D(0, 0);
            c.tilt_stiffness_nm_per_rad += q.area_weight * tilt.dot(D * tilt);
        }
}

std::vector<ChuckContactState> summarise(const std::vector<ContactFace>& faces, const std::vector<ContactPointState>& s,
                                         const SupportEffects& effects) {
    std::vector<ChuckContactState> out(effects.chucks.size());
    std::vector<double> phi_lo(out.size(), M_PI), phi_hi(out.size(), -M_PI);
    for (size_t c = 0; c < out.size(); ++c) {
        out[c].chuck = effects.chucks[c].placement.chuck;
        out[c].z_from_m = INFINITY;
        out[c].z_to_m = -INFINITY;
    }
    size_t k = 0;
    for (const ContactFace& f : faces)
        for (const ContactPoint& q : f.points) {
            ChuckContactState& c = out[f.chuck];
            ++c.points;
            const ContactPointState& p = s[k++];
            if (!p.closed()) continue;
            ++c.closed_points;
            const double phi = std::atan2(q.x[0], q.x[1]);  // from the top (+y), towards +x
            phi_lo[f.chuck] = std::min(phi_lo[f.chuck], phi);
            phi_hi[f.chuck] = std::max(phi_hi[f.chuck], phi);
            c.z_from_m = std::min(c.z_from_m, q.x[2]);
            c.z_to_m = std::max(c.z_to_m, q.x[2]);
            c.closed_area_m2 += q.area_weight;
            c.vertical_force_n += p.p * q.area_weight * q.normal()[1];
            c.max_pressure_pa = std::max(c.max_pressure_pa, p.p);
        }
    for (size_t c = 0; c < out.size(); ++c)
        if (out[c].closed_points > 0) out[c].arc_deg = (phi_hi[c] - phi_lo[c]) * 180 / M_PI;
    add_support_stiffness(faces, s, effects, out);
    std::erase_if(out, [](const ChuckContactState& c) { return c.points == 0; });
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
    Iterate it = first_iterate(faces);
    GravityContact out;
    for (int k = 1; k <= kMaxContactIterations; ++k) {
        const std::vector<char> before = it.active;
        const std::vector<double> d_new = newton_step(ksp, base.K(), K_work, F_g, faces, it, effects, dofs);
        double alpha = 1;
        const double moved = advance(it, d_new, faces, effects, k == 1, alpha);
        const int closed = static_cast<int>(std::count(it.active.begin(), it.active.end(), 1));
        out.closed_history.push_back(closed);
        say("      static contact, iteration " + std::to_string(k) + ": " + std::to_string(closed) + " of " +
            std::to_string(it.active.size()) + " points closed" + (alpha < 1 ? ", step " + significant(alpha) : ""));
        if (closed == 0)
            throw SolveError("the static solve under gravity opened every contact point: the roll no longer rests "
                             "on its chucks (is the clearance larger than the bore allows?)");
        if (k > 1 && it.active == before && alpha == 1 && moved < kConvergedStep) {
            out.iterations = k;
            for (size_t i = 0; i < it.d.size(); ++i) out.state.push_back({it.d[i], it.p[i]});
            out.chucks = summarise(faces, out.state, effects);
            return out;
        }
    }
    throw SolveError("the contact under gravity did not settle in " + std::to_string(kMaxContactIterations) +
                     " active-set iterations (closed points per iteration cycle); expected a finer mesh or a "
                     "larger clearance");
}

std::vector<std::string> contact_state_lines(const GravityContact& contact, double roll_weight_n) {
    std::vector<std::string> lines;
    for (const ChuckContactState& c : contact.chucks)
        lines.push_back("chuck " + c.chuck + ": the static contact under gravity (" +
                        std::to_string(contact.iterations) + " active-set iterations; frictionless, held about the "
                        "axis by a tangential spring of " + significant(kStaticTangentialFraction, 1) +
                        " k_n) is closed over " +
                        significant(c.arc_deg, 3) + " deg of arc at the top and z = " + significant(c.z_from_m * 1e3, 4) +
                        " to " + significant(c.z_to_m * 1e3, 4) + " mm (" + std::to_string(c.closed_points) + " of " +
                        std::to_string(c.points) + " points), carries " + significant(c.vertical_force_n, 4) +
                        " N of the roll's " + significant(roll_weight_n, 4) + " N, peak pressure " +
                        significant(c.max_pressure_pa / 1e3, 3) + " kPa; holds the core by " +
                        significant(c.vertical_stiffness_n_per_m, 3) + " N/m vertically, " +
                        significant(c.horizontal_stiffness_n_per_m, 3) + " N/m sideways, " +
                        significant(c.tilt_stiffness_nm_per_rad, 3) + " N m/rad in tilt");
    return lines;
}

}  // namespace coremodal
