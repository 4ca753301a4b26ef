// The harmonic level's assembled K_n on a chuck scene in elastic bearings
// with frames: rigid motions of the whole model load only the supports, by
// exactly the stiffnesses the scene gives (docs/theory/harmonic.md, "Supports").
#include "assembly/harmonic_system.hpp"

#include "models/part_materials.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

Scene stand_scene(bool frames) {
    const Scene s = testing::with_chucks(testing::paper_core(0.8, 16, 12), InterfaceKind::spring);
    if (frames) return testing::on_elastic_bearings(s, 3e8, 4e6, 25.0, 6e7);
    return testing::on_elastic_bearings(s, 3e8, 4e6);
}

// x^T K x for a field given per node as (U, V, W) of (r, z), frame DOFs set to `frame`.
template <class F>
double energy(const HarmonicSystem& system, const SectionMesh& mesh, F field, double frame) {
    PetscVector x, Kx;
    COREMODAL_PETSC(MatCreateVecs(system.operators.K(), x.out(), Kx.out()));
    for (int node = 0; node < mesh.n_nodes(); ++node) {
        const Eigen::Vector3d u = field(mesh.nodes[node][0], mesh.nodes[node][1]);
        for (int c = 0; c < 3; ++c)
            if (const int d = system.dofs.of_component[3 * node + c]; d >= 0)
                COREMODAL_PETSC(VecSetValue(x, d, u[c], INSERT_VALUES));
    }
    for (int d : system.dofs.frame)
        if (d >= 0) COREMODAL_PETSC(VecSetValue(x, d, frame, INSERT_VALUES));
    COREMODAL_PETSC(VecAssemblyBegin(x));
    COREMODAL_PETSC(VecAssemblyEnd(x));
    COREMODAL_PETSC(MatMult(system.operators.K(), x, Kx));
    PetscScalar e;
    COREMODAL_PETSC(VecDot(x, Kx, &e));
    return e;
}

}  // namespace

TEST_CASE("Harmonic assembly: rigid motions load the bearings and frames by exactly their stiffnesses",
          "[harmonic][assembly]") {
    for (const bool frames : {false, true}) {
        INFO("frames: " << frames);
        const Scene s = stand_scene(frames);
        const SectionMesh mesh = make_section_mesh(make_tube_section(s), s.supports.clamps);
        const auto materials = part_materials(s, mesh.part_names, "test");
        const ChuckSpec& c = s.supports.chucks[0];
        const double kr = c.bearing.radial_stiffness, kt = c.bearing.tilting_stiffness;
        const double kf = frames ? *c.bearing.frame_stiffness : 0.0;
        const double R = c.shaft_diameter / 2, A = M_PI * R * R, I = M_PI * std::pow(R, 4) / 4;
        const double z_left = -c.shaft_length, z_right = s.core.length + c.shaft_length;
        const HarmonicSystem h0 = assemble_harmonic(s, mesh, materials, 0);
        const HarmonicSystem h1 = assemble_harmonic(s, mesh, materials, 1);
        const auto sideways = [](double, double) { return Eigen::Vector3d(1, 1, 0); };
        const auto tilt = [](double r, double z) { return Eigen::Vector3d(z, z, -r); };
        const auto axial = [](double, double) { return Eigen::Vector3d(0, 0, 1); };
        const auto twist = [](double r, double) { return Eigen::Vector3d(0, r, 0); };
        // The spring layers' facing points lie a clearance apart radially: a
        // motion that varies with r (tilt: u_z = -x; twist: u_theta = r)
        // stretches them by that clearance (zero-length springs across the
        // gap, as in the solid): k_t (ri - rb)^2 times the band's area, and
        // half of it in n = 1 (cos^2 over the circle).
        const double ri = s.core.inner_diameter / 2, rb = c.body_diameter / 2, w = c.expanding[0].width;
        const double layer = 2 * c.interface.tangential_stiffness * std::pow(ri - rb, 2) * 2 * M_PI * ri * w;
        // x^T K x = sum over the two bearings of k X^2 (the energy is half of it).
        if (frames) {
            // The frames move with the roll: the bearings are unloaded, the frame springs carry it.
            CHECK(energy(h1, mesh, sideways, 1.0) == Approx(2 * kf).epsilon(1e-9));
            CHECK(energy(h0, mesh, axial, 1.0) == Approx(2 * kf).epsilon(1e-9));
        }
        // The frames held still (or absent): the bearings carry the motion.
        CHECK(energy(h1, mesh, sideways, 0.0) == Approx(2 * kr).epsilon(1e-9));
        // Tilt about y through the origin: each face turns by 1 rad and moves sideways by its z.
        CHECK(energy(h1, mesh, tilt, 0.0) ==
              Approx(2 * kt + kr * (z_left * z_left + z_right * z_right) + layer / 2).epsilon(1e-9));
        // Axial translation: c_z = k_tilt / I spread over the face, as in the solid.
        CHECK(energy(h0, mesh, axial, 0.0) == Approx(2 * kt / I * A).epsilon(1e-9));
        // Rotation about the axis: c_r on u_theta over the face, k_radial / A * polar moment.
        CHECK(energy(h0, mesh, twist, 0.0) == Approx(2 * kr / A * (M_PI * std::pow(R, 4) / 2) + layer).epsilon(1e-9));
    }
}
