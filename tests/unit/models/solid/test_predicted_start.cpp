// The harmonic level's modes at the solid mesh's nodes (issue 39): a field
// of wave number n given on a revolved section, read at nodes between its
// planes, against the same field in closed form.
#include "models/solid/predicted_start.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

// A section of 2 x 3 quad8 cells over r in [0.05, 0.08], z in [0, 0.3].
SectionMesh small_section() {
    SectionMesh s;
    s.part_names = {"core"};
    constexpr int nr = 2, nz = 3;
    const auto node = [&](double r, double z) {
        for (int i = 0; i < s.n_nodes(); ++i)
            if (std::abs(s.nodes[i][0] - r) < 1e-12 && std::abs(s.nodes[i][1] - z) < 1e-12) return i;
        s.nodes.push_back({r, z});
        return s.n_nodes() - 1;
    };
    for (int i = 0; i < nr; ++i)
        for (int j = 0; j < nz; ++j) {
            const double r0 = 0.05 + 0.015 * i, r1 = r0 + 0.015, z0 = 0.1 * j, z1 = z0 + 0.1;
            const double rm = 0.5 * (r0 + r1), zm = 0.5 * (z0 + z1);
            s.cells.push_back({node(r0, z0), node(r1, z0), node(r1, z1), node(r0, z1), node(rm, z0), node(r1, zm),
                               node(rm, z1), node(r0, zm)});
            s.cell_part.push_back(0);
        }
    return s;
}

// The cos family of wave number n (harmonic_shapes.hpp): u_r = U cos n theta,
// u_theta = -V sin n theta, u_z = W cos n theta, with U, V, W smooth in (r, z).
std::array<double, 3> field(int n, double r, double theta, double z) {
    const double U = 1 + 10 * r, V = 0.5 + z, W = r * z;
    const double ur = U * std::cos(n * theta), ut = -V * std::sin(n * theta), uz = W * std::cos(n * theta);
    return {ur * std::cos(theta) - ut * std::sin(theta), ur * std::sin(theta) + ut * std::cos(theta), uz};
}

}  // namespace

TEST_CASE("A harmonic mode read at a solid mesh's nodes between the revolved planes", "[models][predicted_start]") {
    constexpr int kAround = 16;  // 32 planes, dtheta = pi / 16
    constexpr int kWave = 2;
    const RevolvedMesh revolved = revolve_section(small_section(), kAround);
    Mode mode;
    for (std::size_t i = 0; i < revolved.mesh.nodes.size(); ++i) {
        const auto& x = revolved.mesh.nodes[i];
        const auto u = field(kWave, std::hypot(x[0], x[1]), revolved.theta[i], x[2]);
        mode.shape.insert(mode.shape.end(), u.begin(), u.end());
    }
    // The "solid": every section node at 7 angles that are not the planes',
    // one of them eliminated (a clamped node).
    Mesh solid;
    const SectionMesh section = small_section();
    for (const auto& rz : section.nodes)
        for (int k = 0; k < 7; ++k) {
            const double theta = 0.3 + 0.87 * k;
            solid.nodes.push_back({rz[0] * std::cos(theta), rz[0] * std::sin(theta), rz[1]});
        }
    const DofMap dofs = make_dof_map(solid.n_nodes(), {0});
    PetscMatrix K;
    COREMODAL_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, dofs.n_dofs, dofs.n_dofs, 1, nullptr, K.out()));
    const std::vector<PetscVector> on_solid = harmonic_modes_on_solid(revolved, {mode}, solid, dofs, K);
    REQUIRE(on_solid.size() == 1);
    const PetscScalar* x;
    COREMODAL_PETSC(VecGetArrayRead(on_solid[0], &x));
    // Linear interpolation in theta of a component of wave number n over a
    // step h errs by at most (n h)^2 / 8 of its amplitude (the bound
    // max|f''| h^2 / 8); a Cartesian component mixes u_r and u_theta, so by
    // at most (max U + max V) (n h)^2 / 8. A mid-side node of the section
    // turns into every other plane only: h = 2 pi / 16 for it, 0.2 here.
    const double h = 2 * M_PI / kAround, bound = (1.8 + 0.8) * std::pow(kWave * h, 2) / 8;
    double worst = 0;
    for (int node = 1; node < solid.n_nodes(); ++node) {
        const auto& p = solid.nodes[node];
        const auto u = field(kWave, std::hypot(p[0], p[1]), std::atan2(p[1], p[0]), p[2]);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(x[dofs.dof(node, c)] - u[c]));
    }
    COREMODAL_PETSC(VecRestoreArrayRead(on_solid[0], &x));
    CHECK(worst < bound);
    CHECK(worst > 0);  // between the planes: interpolated, not copied
}
