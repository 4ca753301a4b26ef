// Hard cases that break naive modal solvers (the first of issue 5's list).
// Each asserts completeness, verification and the invariant named.
#include "verification/tube_scenes.hpp"

#include "assembly/petsc_system.hpp"
#include "eigensolve/modal_solver.hpp"
#include "geometry/tube_model.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;
using namespace coremodal::testing;

TEST_CASE("Free-free: the six rigid modes are found and separated from the first elastic one whatever the shift",
          "[hard]") {
    Scene s = steel_tube(0.100, 0.090, 1.0, 1, 12, 10, 10);
    GmshSession gmsh;
    build_tube_model(make_tube_section(s), {}, "hex20");
    const Mesh mesh = read_current_gmsh_mesh("test");
    const DofMap dofs = make_dof_map(mesh.n_nodes(), {});
    const PetscSystem sys = assemble_petsc(mesh, {{stiffness_cylindrical(s.core.material), 7850}}, dofs);
    const double lambda_beam = std::pow(2 * M_PI * 500.0, 2);  // the order of the first bending mode
    std::vector<std::vector<double>> spectra;
    // The shift is -lambda_scale / 2: from very close to zero (a nearly
    // singular factor) to far below the wanted modes (slow convergence).
    for (double scale : {1e-4, 1.0, 100.0}) {
        SolveRequest request;
        request.n_modes = 10;
        request.lambda_scale = scale * lambda_beam;
        const auto solved = solve_modes(sys.K, sys.M, request, [](const std::string&) {});
        CHECK(solved.verification.complete);
        CHECK(solved.verification.max_relative_residual < 1e-8);
        spectra.push_back(solved.eigenvalues);
    }
    for (const auto& spectrum : spectra) {
        REQUIRE(spectrum.size() >= 10);
        // Rigid: |lambda| ~ 1e-9 of the first elastic eigenvalue or less.
        for (int i = 0; i < 6; ++i) CHECK(std::abs(spectrum[i]) < 1e-6 * spectrum[6]);
        for (int i = 6; i < 10; ++i)
            CHECK(spectrum[i] == Approx(spectra[1][i]).epsilon(1e-8));
    }
}

TEST_CASE("Units: the same scene in mm/MPa strings and in SI numbers gives identical results", "[hard]") {
    const std::string with_units = R"(
[core]
inner_diameter = "76 mm"
outer_diameter = "106 mm"
length = "1500 mm"
material = { E = "6500 MPa", nu = 0.3, density = "0.92 g/cm^3" }
[supports]
type = "clamped"
[supports.left]
length = "70 mm"
[analysis]
modes = 6
[mesh]
level = "coarse"
)";
    const std::string si = R"(
[core]
inner_diameter = 0.076
outer_diameter = 0.106
length = 1.5
material = { E = 6.5e9, nu = 0.3, density = 920 }
[supports]
type = "clamped"
[supports.left]
length = 0.07
[analysis]
modes = 6
[mesh]
level = "coarse"
)";
    const auto a = solve_quietly(parse_case_text(with_units, "units.toml"));
    const auto b = solve_quietly(parse_case_text(si, "si.toml"));
    REQUIRE(a.modes.modes.size() == b.modes.modes.size());
    for (size_t i = 0; i < a.modes.modes.size(); ++i)
        CHECK(a.modes.modes[i].frequency_hz == Approx(b.modes.modes[i].frequency_hz).epsilon(1e-12));
}

TEST_CASE("Very slender: at L/Do = 60 the beam limit is reached", "[hard]") {
    // Steel tube Do 50 mm, 3 m: shear and rotary inertia change the first
    // free-free bending frequency by ~0.1 %; Euler-Bernoulli within 0.5 %.
    const auto r = solve_quietly(steel_tube(0.050, 0.044, 3.0, 1, 12, 60, 8));
    CHECK(r.modes.verification.complete);
    CHECK(r.beam.fe_over_euler_bernoulli == Approx(1.0).epsilon(5e-3));
}

TEST_CASE("Thin wall: at wall/Di = 0.02 the default mesh does not lock", "[hard]") {
    // ISO 11093-8's thinnest wall on a 76 mm core: 1.52 mm, 1.5 m, free-free.
    // Converged reference: the "fine" level (398,736 DOFs, 4 elements through
    // the wall) gives 112.9749 Hz; coarse and default agree with it to 4e-6,
    // so locking (which would stiffen the coarse meshes first) is absent.
    const std::string thin = R"(
[core]
inner_diameter = "76 mm"
wall = "1.52 mm"
length = "1.5 m"
material = "paperboard_core"
[supports]
type = "free"
[analysis]
modes = 8
)";
    const auto r = solve_quietly(parse_case_text(thin, "thin.toml"));
    CHECK(r.modes.verification.complete);
    CHECK(r.modes.modes[6].label.type == "bending");
    CHECK(r.beam.fe_first_bending_hz == Approx(112.9749).epsilon(0.01));  // the issue's 1 %
    CHECK(r.beam.fe_first_bending_hz == Approx(112.9749).epsilon(1e-4));  // what it achieves
    // A thin free tube at L/Do = 19 is a Timoshenko beam to shell effects (~0.1 %).
    CHECK(r.beam.fe_over_timoshenko == Approx(1.0).epsilon(5e-3));
}
