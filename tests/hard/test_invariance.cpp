// Hard cases: strong orthotropy must not make the answer depend on how the
// unknowns are numbered or how the mesh is turned about the axis, and dense
// clusters of ovalling modes must come out whole.
#include "hard/mesh_transforms.hpp"
#include "verification/tube_scenes.hpp"

#include "assembly/petsc_system.hpp"
#include "eigensolve/modal_solver.hpp"
#include "geometry/tube_model.hpp"
#include "mesh/gmsh_mesh.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

// E_z / E_r = 650 and transverse shear 100x below the in-plane shear: far
// beyond paperboard's already strong orthotropy.
OrthotropicMaterial extreme_paperboard() {
    OrthotropicMaterial m;
    m.name = "extreme";
    m.E_r = 10e6, m.E_theta = 4e9, m.E_z = 6.5e9;
    m.G_rtheta = 18e6, m.G_rz = 18e6, m.G_thetaz = 1.8e9;
    m.nu_rtheta = 0.001, m.nu_rz = 0.001, m.nu_thetaz = 0.3;
    m.density = 920;
    return m;
}

Mesh clamped_tube_mesh(const Scene& s) {
    GmshSession gmsh;
    build_tube_model(make_tube_section(s), s.supports.clamps, "hex20");
    return read_current_gmsh_mesh("test");
}

std::vector<double> lowest_eigenvalues(const Mesh& mesh, const OrthotropicMaterial& material, int n) {
    std::vector<int> clamped;
    for (const auto& name : {"clamp_left", "clamp_right"})
        for (int node : mesh.node_groups.at(name)) clamped.push_back(node);
    std::sort(clamped.begin(), clamped.end());
    clamped.erase(std::unique(clamped.begin(), clamped.end()), clamped.end());
    const DofMap dofs = make_dof_map(mesh.n_nodes(), clamped);
    const PetscSystem sys = assemble_petsc(mesh, {{stiffness_cylindrical(material), material.density}}, dofs);
    SolveRequest request;
    request.n_modes = n;
    request.lambda_scale = std::pow(2 * M_PI * 100.0, 2);
    const auto solved = solve_modes(sys.K, sys.M, request, [](const std::string&) {});
    CHECK(solved.verification.complete);
    CHECK(solved.verification.max_relative_residual < 1e-8);
    return solved.eigenvalues;
}

}  // namespace

TEST_CASE("Strong orthotropy: frequencies do not depend on the numbering of unknowns or the mesh's rotation",
          "[hard]") {
    Scene s = clamp_both_ends(steel_tube(0.106, 0.076, 1.0, 2, 16, 16, 8), 0.07);
    const Mesh mesh = clamped_tube_mesh(s);
    const auto material = extreme_paperboard();
    const auto reference = lowest_eigenvalues(mesh, material, 8);
    // The problem is identical; only round-off differs (conditioning ~1e8
    // times machine epsilon leaves eigenvalues equal to ~1e-10).
    const auto renumbered = lowest_eigenvalues(shuffled(mesh, 7), material, 8);
    const auto turned = lowest_eigenvalues(rotated(mesh, 0.3), material, 8);
    REQUIRE(renumbered.size() == reference.size());
    REQUIRE(turned.size() == reference.size());
    for (size_t i = 0; i < reference.size(); ++i) {
        CHECK(renumbered[i] == Approx(reference[i]).epsilon(1e-8));
        CHECK(turned[i] == Approx(reference[i]).epsilon(1e-8));
    }
}

TEST_CASE("Clusters: asking for a number of modes that cuts a degenerate pair returns the whole pair", "[hard]") {
    // A thin free tube: 6 rigid modes, then the n = 2 ovalling pair. Seven
    // modes asked cuts the pair; the solver must return both members.
    const auto r = solve_quietly(steel_tube(0.100, 0.096, 0.6, 2, 32, 8, 7));
    REQUIRE(r.modes.modes.size() == 8);
    CHECK(r.modes.verification.complete);
    CHECK(r.modes.modes[6].label.type == "ovalling");
    CHECK(r.modes.modes[7].label.type == "ovalling");
    CHECK(r.modes.modes[6].label.n == 2);
    CHECK(r.modes.modes[7].label.n == 2);
    CHECK(r.modes.modes[7].frequency_hz == Approx(r.modes.modes[6].frequency_hz).epsilon(1e-8));
}
