// Hard cases with chucks (issue 5, cases 4 and 7): a steel chuck bonded to a
// core 2e4 times softer radially; a chuck so loosely held that the roll nearly
// floats; a part held by nothing. Scenes: cases/hard/04, 07 and 07b.
#include "hard/hard_checks.hpp"
#include "hard/mesh_transforms.hpp"
#include "verification/tube_scenes.hpp"

#include "assembly/chuck_supports.hpp"
#include "assembly/petsc_system.hpp"
#include "eigensolve/modal_solver.hpp"
#include "geometry/tube_model.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/gmsh_mesh.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

std::vector<PartMaterial> materials_by_part(const Scene& s, const Mesh& mesh) {
    std::vector<PartMaterial> out;
    for (const auto& part : mesh.part_names) {
        const OrthotropicMaterial& m = part == "core" ? s.core.material : s.supports.chucks.at(0).material;
        out.push_back({stiffness_cylindrical(m), m.density});
    }
    return out;
}

struct Spectrum {
    std::vector<double> eigenvalues;
    std::vector<ModeLabel> labels;
};

// The pipeline's steps 3-6 on a given mesh: supports, DOFs, K and M, verified
// eigenpairs, labels.
Spectrum solve_on(const Scene& s, const Mesh& mesh, int n_modes) {
    const ChuckSupports supports = chuck_supports(s, mesh);
    const DofMap dofs = make_dof_map(mesh.n_nodes(), supports.eliminated, supports.ties);
    const OperatorSet sys = assemble_petsc(mesh, materials_by_part(s, mesh), dofs, supports.couplings);
    SolveRequest request;
    request.n_modes = n_modes;
    request.lambda_scale = std::pow(2 * M_PI * 100.0, 2);
    SolvedModes solved = solve_modes(sys, request, [](const std::string&) {});
    check_verified(solved.verification);
    CHECK(solved.eigenvalues.size() >= static_cast<size_t>(n_modes));
    return {solved.eigenvalues, labels_of(solved, mesh, dofs, request.lambda_scale)};
}

}  // namespace

TEST_CASE("Stiffness contrast 2e4 (steel chuck bonded to 10 MPa paper): numbering and rotation do not matter",
          "[hard][chucks]") {
    const Scene s = hard_case("04-stiffness-contrast.toml");
    REQUIRE(s.supports.chucks.size() == 2);
    REQUIRE(s.supports.chucks[0].interface.kind == InterfaceKind::bonded);
    REQUIRE(s.supports.chucks[0].material.E_r / s.core.material.E_r >= 1e4);  // the contrast
    const int n = s.analysis.n_modes;
    const Mesh mesh = generated_mesh(s);
    const auto reference = solve_on(s, mesh, n);
    const auto renumbered = solve_on(s, shuffled(mesh, 11), n);
    const auto turned = solve_on(s, rotated(mesh, 0.37), n);
    // The same problem; only round-off differs (see the strong-orthotropy case).
    check_invariant(reference, renumbered, turned);
}

// The frequency in `modes` nearest to f.
double nearest_frequency(const std::vector<Mode>& modes, double f) {
    double best = 0;
    for (const Mode& m : modes)
        if (std::abs(m.frequency_hz - f) < std::abs(best - f)) best = m.frequency_hz;
    return best;
}

TEST_CASE("Near-mechanism: a roll on a very soft interface moves as a rigid body on springs, verified and complete",
          "[hard][chucks]") {
    // k_n = 1e5 Pa/m: 1e4 times softer than a chuck that was not expanded.
    // The core floats on the two bands (R = 38 mm, w = 60 mm, centres d = 0.37 m
    // from the middle) as a rigid body; its own modes are above 100 Hz.
    const Scene s = hard_case("07-near-mechanism-soft-chuck.toml");
    REQUIRE(s.supports.chucks.size() == 2);
    const ChuckInterface& interface = s.supports.chucks[0].interface;
    REQUIRE(interface.kind == InterfaceKind::spring);
    CHECK_FALSE(interface.expanded);
    const double kn = interface.normal_stiffness, kt = interface.tangential_stiffness;
    REQUIRE(kn == Approx(1e5));
    REQUIRE(kt == Approx(0.82 * kn));
    const double R = 0.038, w = 0.06, d = 0.37, L = s.core.length;
    REQUIRE(L == Approx(0.9));
    const RunReport r = solve_quietly(s);
    check_verified(r.modes.verification);
    REQUIRE(r.modes.modes.size() >= static_cast<size_t>(s.analysis.n_modes));
    CHECK(r.warnings.empty());  // held, if softly: no "free part" warning
    const double ro = 0.053, ri = 0.038;
    const double mass = s.core.material.density * M_PI * (ro * ro - ri * ri) * L;
    const double band_area = 2 * M_PI * R * w;
    const double k_lateral_band = band_area * (kn + kt) / 2;  // cos^2 + sin^2 over the band
    const auto hz = [](double k, double inertia) { return std::sqrt(k / inertia) / (2 * M_PI); };
    const double f_torsion = hz(2 * kt * band_area * R * R, mass * (ro * ro + ri * ri) / 2);
    const double f_axial = hz(2 * kt * band_area, mass);
    const double f_bounce = hz(2 * k_lateral_band, mass);
    // Rocking: the bands' lateral springs at +-d (and across their width), the
    // axial springs at radius R.
    const double k_rock = 2 * k_lateral_band * (d * d + w * w / 12) + 2 * kt * band_area * R * R / 2;
    const double f_rock = hz(k_rock, mass * (L * L / 12 + (ro * ro + ri * ri) / 4));
    for (double f : {f_torsion, f_axial, f_bounce, f_rock}) CHECK(nearest_frequency(r.modes.modes, f) == Approx(f).epsilon(0.01));
    CHECK(r.modes.modes.front().frequency_hz > 0);
}

TEST_CASE("A part held by nothing is named, and its six rigid modes are found, not garbage", "[hard]") {
    // A clamped core with rest paper whose cells are cut loose from the core
    // (their shared nodes duplicated): the rest paper floats.
    const Scene s = hard_case("07b-rest-paper-cut-loose.toml");
    REQUIRE(s.rest_paper);
    Mesh mesh;
    {
        GmshSession gmsh;
        build_tube_model(make_tube_section(s), s.supports.clamps, s.mesh.element);
        mesh = read_current_gmsh_mesh("test");
    }
    const int paper = static_cast<int>(std::find(mesh.part_names.begin(), mesh.part_names.end(), "rest_paper") -
                                       mesh.part_names.begin());
    std::vector<char> in_core(mesh.n_nodes(), 0);
    for (int c = 0; c < mesh.n_cells(); ++c)
        if (mesh.cell_part[c] != paper)
            for (int a = 0; a < mesh.nodes_per_cell(); ++a) in_core[mesh.cell(c)[a]] = 1;
    std::map<int, int> copy_of;  // nodes the paper shares with the core get a copy
    for (int c = 0; c < mesh.n_cells(); ++c) {
        if (mesh.cell_part[c] != paper) continue;
        for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
            int& v = mesh.cells[static_cast<size_t>(c) * mesh.nodes_per_cell() + a];
            if (!in_core[v]) continue;
            if (!copy_of.count(v)) {
                copy_of[v] = mesh.n_nodes();
                mesh.nodes.push_back(mesh.nodes[v]);
            }
            v = copy_of[v];
        }
    }
    std::vector<int> clamped;
    for (const auto& g : {"clamp_left", "clamp_right"})
        clamped.insert(clamped.end(), mesh.node_groups.at(g).begin(), mesh.node_groups.at(g).end());
    const auto warnings = unheld_parts(mesh, clamped);
    REQUIRE(warnings.size() == 1);
    CHECK_THAT(warnings[0], Catch::Contains("'rest_paper'") && Catch::Contains("six rigid-body modes"));

    std::sort(clamped.begin(), clamped.end());
    clamped.erase(std::unique(clamped.begin(), clamped.end()), clamped.end());
    const DofMap dofs = make_dof_map(mesh.n_nodes(), clamped);
    std::vector<PartMaterial> materials;
    for (const auto& part : mesh.part_names) {
        const OrthotropicMaterial& m = part == "rest_paper" ? s.rest_paper->material : s.core.material;
        materials.push_back({stiffness_cylindrical(m), m.density});
    }
    const OperatorSet sys = assemble_petsc(mesh, materials, dofs);
    SolveRequest request;
    request.n_modes = s.analysis.n_modes;
    request.lambda_scale = std::pow(2 * M_PI * 100.0, 2);
    const SolvedModes solved = solve_modes(sys, request, [](const std::string&) {});
    check_verified(solved.verification);
    REQUIRE(solved.eigenvalues.size() >= static_cast<size_t>(request.n_modes));
    // Six eigenvalues at zero (to round-off against the elastic scale), then elastic ones.
    for (int i = 0; i < 6; ++i) CHECK(std::abs(solved.eigenvalues[i]) < kRigidEigenvalueFraction * request.lambda_scale);
    CHECK(solved.eigenvalues[6] > 0.01 * request.lambda_scale);
    // The paper floats as a body: the six zero modes are labelled rigid.
    const auto labels = labels_of(solved, mesh, dofs, request.lambda_scale);
    for (int i = 0; i < 6; ++i) CHECK(labels[i].type == "rigid");
}

TEST_CASE("The unheld-part case file as written (paper bonded) is held: no warning, verified", "[hard]") {
    const RunReport r = solve_quietly(hard_case("07b-rest-paper-cut-loose.toml"));
    check_verified(r.modes.verification);
    CHECK(r.warnings.empty());
    REQUIRE_FALSE(r.modes.modes.empty());
    CHECK(r.modes.modes.front().label.type != "rigid");
}
