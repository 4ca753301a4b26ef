// The solid level's centrifugal term (models/solid/centrifugal_prestress,
// effects/rotation.hpp) against independent truths: the stresses of a thin
// spinning annular disc (Timoshenko & Goodier's plane-stress closed form),
// the virial of a free body (a rigid tilt's K_sigma1 and M_L cancel), and a
// free thin ring spinning as fast as it vibrates (Bryan's exact form).
#include "verification/tube_scenes.hpp"

#include "assembly/chuck_supports.hpp"
#include "assembly/petsc_system.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "models/part_materials.hpp"
#include "models/solid/centrifugal_prestress.hpp"
#include "models/solid/rotating_solid.hpp"
#include "models/solid/solid_level.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

// A generated solid scene's mesh, DOFs, materials and operators (as a run's steps 2-4).
struct SolidSetup {
    Mesh mesh;
    DofMap dofs;
    std::vector<PartMaterial> materials;
    OperatorSet operators;
};

SolidSetup solid_setup(const Scene& s) {
    SolidSetup out{make_solid_mesh(s), {}, {}, {}};
    const ChuckSupports chucks = chuck_supports(s, out.mesh);
    LevelModes summary;
    out.dofs = solid_dofs(s, out.mesh, chucks, summary);
    out.materials = part_materials(s, out.mesh.part_names, "generated mesh");
    out.operators = assemble_petsc(out.mesh, out.materials, out.dofs, chucks.couplings);
    return out;
}

PetscVector field(Mat A, const SolidSetup& s, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u) {
    PetscVector v;
    COREMODAL_PETSC(MatCreateVecs(A, v.out(), nullptr));
    for (int n = 0; n < s.mesh.n_nodes(); ++n) {
        const auto& p = s.mesh.nodes[n];
        const Eigen::Vector3d value = u({p[0], p[1], p[2]});
        for (int c = 0; c < 3; ++c)
            if (const int d = s.dofs.dof(n, c); d >= 0) COREMODAL_PETSC(VecSetValue(v, d, value[c], INSERT_VALUES));
    }
    COREMODAL_PETSC(VecAssemblyBegin(v));
    COREMODAL_PETSC(VecAssemblyEnd(v));
    return v;
}

const RotatingMode& first(const std::vector<RotatingMode>& modes, const std::string& type, int n, Whirl whirl) {
    for (const RotatingMode& m : modes)
        if (m.label.type == type && m.label.n == n && m.whirl == whirl) return m;
    FAIL("no " << type << " n = " << n << " mode with whirl " << whirl_name(whirl));
    throw;
}

}  // namespace

TEST_CASE("A thin spinning annular disc carries Timoshenko and Goodier's radial and hoop stresses",
          "[rotation][solid][centrifugal]") {
    // Steel, a = 0.2 m, b = 0.5 m, h = 10 mm, free: 8 hex20 across the
    // width, 32 around, 1 through the thickness. Per unit Omega^2
    //   sigma_r = (3 + nu)/8 rho (a^2 + b^2 - a^2 b^2/r^2 - r^2)
    //   sigma_t = (3 + nu)/8 rho (a^2 + b^2 + a^2 b^2/r^2 - (1 + 3 nu)/(3 + nu) r^2)
    // (plane stress). 16 hex20 across the width, 64 around, 1 through the
    // thickness. The 3D disc departs from plane stress by about
    // nu (h/b)^2 / 8 ~ 2e-5 of the stresses; the rest is the mesh's: the
    // largest error at any integration point, as a share of the peak hoop
    // stress, measured 5.5e-3 on 8 x 32 cells, 2.4e-3 (radial) and 5.8e-3
    // (hoop) on 16 x 32, 4.9e-3 and 2.3e-3 on 8 x 64, 1.7e-3 and 1.8e-3 on
    // 16 x 64: falling as either direction is refined. The tolerance is the
    // last mesh's error with 40 % room.
    const double a = 0.2, b = 0.5, nu = 0.3, rho = 7850;
    const Scene disc = testing::steel_tube(2 * b, 2 * a, 0.01, 16, 64, 1);
    const SolidSetup s = solid_setup(disc);
    const CentrifugalState state = solve_centrifugal_state(s.operators, s.mesh, s.materials, s.dofs);
    CHECK(state.pinned.size() == 6);  // free: every rigid motion pinned
    CHECK(state.load_work_on_pinned < 1e-12);
    const double c = (3 + nu) / 8 * rho;
    const auto sigma_r = [&](double r) { return c * (a * a + b * b - a * a * b * b / (r * r) - r * r); };
    const auto sigma_t = [&](double r) {
        return c * (a * a + b * b + a * a * b * b / (r * r) - (1 + 3 * nu) / (3 + nu) * r * r);
    };
    const double peak = sigma_t(a);
    double worst_r = 0, worst_t = 0, worst_z = 0;
    for (const PointStress& p : centrifugal_stresses(s.mesh, s.materials, state)) {
        const double r = std::hypot(p.x.x(), p.x.y());
        const Eigen::Vector3d e_r(p.x.x() / r, p.x.y() / r, 0), e_t(-e_r.y(), e_r.x(), 0);
        worst_r = std::max(worst_r, std::abs(e_r.dot(p.sigma * e_r) - sigma_r(r)) / peak);
        worst_t = std::max(worst_t, std::abs(e_t.dot(p.sigma * e_t) - sigma_t(r)) / peak);
        worst_z = std::max(worst_z, std::abs(p.sigma(2, 2)) / peak);
    }
    INFO("largest errors against the closed form, share of the peak hoop stress " << peak << " Pa s^2: radial "
                                                                                   << worst_r << ", hoop " << worst_t
                                                                                   << ", axial " << worst_z);
    CHECK(worst_r < 2.5e-3);
    CHECK(worst_t < 2.5e-3);
    CHECK(worst_z < 1e-3);  // plane stress: measured 3.3e-4
}

TEST_CASE("K_Omega of a free body: nothing on a rigid translation, and a rigid tilt's two parts cancel",
          "[rotation][solid][centrifugal]") {
    // Translations: grad u = 0 and d/dtheta u = 0. Tilt about x, (0, -z, y):
    // t^T K_sigma1 t = int sigma_yy + sigma_zz dV, which the static solve's
    // weak form with the linear test fields y e_y and z e_z gives exactly as
    // int rho y^2 dV and 0 (if the pins carry no reaction); t^T M_L t = int
    // rho x^2 dV; on a mesh symmetric under x <-> y they cancel to round-off.
    const Scene tube = testing::steel_tube(0.106, 0.076, 0.3, 1, 8, 4);
    SolidSetup s = solid_setup(tube);
    const CentrifugalState state = solve_centrifugal_state(s.operators, s.mesh, s.materials, s.dofs);
    add_centrifugal_term(s.operators, s.mesh, s.materials, s.dofs, state, CentrifugalPart::stationary_frame);
    Mat K_omega = s.operators[Term::centrifugal];
    OperatorSet stress_only = solid_setup(tube).operators;
    add_centrifugal_term(stress_only, s.mesh, s.materials, s.dofs, state, CentrifugalPart::stress_stiffness_only);
    for (int c = 0; c < 3; ++c) {
        const PetscVector t = field(K_omega, s, [c](const Eigen::Vector3d&) { return Eigen::Vector3d::Unit(c); });
        PetscVector Kt;
        COREMODAL_PETSC(VecDuplicate(t, Kt.out()));
        COREMODAL_PETSC(MatMult(K_omega, t, Kt));
        PetscReal norm = 0;
        COREMODAL_PETSC(MatNorm(K_omega, NORM_1, &norm));
        CHECK(vector_norm(Kt) <= 1e-13 * norm * vector_norm(t));
    }
    const PetscVector tilt = field(K_omega, s, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(0, -x.z(), x.y()); });
    const double stress_part = quadratic_form(stress_only[Term::centrifugal], tilt);
    const double whole = quadratic_form(K_omega, tilt);
    INFO("tilt: t^T K_sigma1 t = " << stress_part << ", t^T K_Omega t = " << whole);
    CHECK(stress_part > 0);
    CHECK(std::abs(whole) <= 1e-10 * stress_part);
}

TEST_CASE("A free thin ring spinning as fast as it vibrates: Bryan's exact form with the centrifugal term",
          "[rotation][solid][centrifugal][long]") {
    // The thin steel ring of the gyroscopic test (R ~ 0.5 m, t/R = 0.01,
    // 2 x 128 x 2 hex20), at f_rot = 0.6 f0 (f0 its own n = 2 frequency at
    // rest). The hoop prestress rho R^2 Omega^2 and the spin softening M_L
    // cancel for an inextensional wave, leaving in the stationary frame
    //   f = sqrt(f0^2 + beta^2 f_rot^2) +- beta f_rot,  beta = n (n^2 - 1)/(n^2 + 1) = 1.2.
    // Without M_L the ring comes out stiffer, without K_sigma1 softer, by
    // ~(2 f_rot / f0)^2 of f0^2 (measured below when written: docs/theory/rotation.md).
    // The tolerance: the ring's beta at low speed is 1.20002 (its finite
    // thickness), and the thin-ring cancellation holds to ~(t/R)^2 = 1e-4.
    Scene ring = testing::steel_tube(1.0, 0.99, 0.02, 2, 128, 2, 16);
    ring.model = ModelChoice::solid;
    const RotatingSolid solid(ring, 16, {.centrifugal_stiffening = true});
    const double f0 = first(solid.modes_at(0.0), "ovalling", 2, Whirl::none).frequency_hz;
    const double f_rot = 0.6 * f0, beta = 1.2;
    const std::vector<RotatingMode> spin = solid.modes_at(f_rot);
    const double fw = first(spin, "ovalling", 2, Whirl::forward).frequency_hz;
    const double bw = first(spin, "ovalling", 2, Whirl::backward).frequency_hz;
    const double centre = std::sqrt(f0 * f0 + beta * beta * f_rot * f_rot);
    INFO("f0 = " << f0 << " Hz, f_rot = " << f_rot << " Hz: FW " << fw << " (Bryan " << centre + beta * f_rot
                 << "), BW " << bw << " (Bryan " << centre - beta * f_rot << ")");
    CHECK(fw == Approx(centre + beta * f_rot).epsilon(1e-4));
    CHECK(bw == Approx(centre - beta * f_rot).epsilon(1e-4));
    CHECK(solid.pinned_rigid_motions().size() == 6);
    CHECK(solid.max_relative_residual() < 1e-8);
}
