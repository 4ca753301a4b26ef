// The harmonic model level's steps 2–6, numbered as in a run, with one
// eigenproblem per wave number n in steps 3–5.
#include "models/harmonic/harmonic_level.hpp"

#include "assembly/chuck_supports.hpp"
#include "assembly/harmonic_system.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/stopwatch.hpp"
#include "geometry/tube_model.hpp"
#include "eigensolve/modal_solver.hpp"
#include "geometry/section_mesh.hpp"
#include "modes/classify.hpp"
#include "modes/mac.hpp"
#include "models/choose.hpp"
#include "models/harmonic/harmonic_search.hpp"
#include "models/harmonic/harmonic_shapes.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"
#include "modes/mode_shapes.hpp"

#include "scene/mesh_rule.hpp"
#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// One harmonic's verified modes, values gathered on rank 0.
struct HarmonicModes {
    int n = 0;
    HarmonicDofs dofs;
    std::vector<double> eigenvalues, residuals;
    std::vector<std::vector<double>> vectors;
    std::vector<std::array<double, 3>> gamma;  // x^T M r for r = x, z, rz (RigidMotion order)
    Verification verification;
    bool solved = false;  // false: only counted, and no eigenvalue lies below the band edge
    double lowest = 0;    // when only counted: its lowest eigenvalue
};

// M r for a field r given as plain values on the DOFs.
PetscVector mass_times(Mat M, const std::vector<double>& values) {
    PetscVector r, Mr;
    COREMODAL_PETSC(MatCreateVecs(M, r.out(), Mr.out()));
    PetscInt lo, hi;
    COREMODAL_PETSC(VecGetOwnershipRange(r, &lo, &hi));
    PetscScalar* v;
    COREMODAL_PETSC(VecGetArray(r, &v));
    for (PetscInt i = lo; i < hi; ++i) v[i - lo] = values[i];
    COREMODAL_PETSC(VecRestoreArray(r, &v));
    COREMODAL_PETSC(MatMult(M, r, Mr));
    return Mr;
}

HarmonicModes solve_harmonic(const Scene& scene, HarmonicSystem& system, const SectionMesh& section,
                             const SolveRequest& request) {
    HarmonicModes h;
    h.n = system.n;
    h.dofs = system.dofs;
    h.solved = true;
    const SolvedModes solved =
        solve_for_case(scene, system.operators, request, [](const std::string&) {},
                       "the problem of wave number n = " + std::to_string(system.n) + " (each is solved on its own): ");
    h.eigenvalues = solved.eigenvalues;
    h.residuals = solved.relative_residuals;
    h.verification = solved.verification;
    // Rigid motions live in n = 0 (along and about z) and n = 1 (sideways) only.
    const bool has_rigid_motions = system.n <= 1;
    std::array<PetscVector, 3> M_r;
    if (has_rigid_motions)
        for (int d = 0; d < 3; ++d)
            M_r[d] = mass_times(system.operators.M(), harmonic_rigid_field(section, system.dofs, system.n, static_cast<RigidMotion>(d)));
    for (const PetscVector& x : solved.vectors) {
        std::array<double, 3> g{};
        if (has_rigid_motions)
            for (int d = 0; d < 3; ++d) COREMODAL_PETSC(VecDot(x, M_r[d], &g[d]));
        h.gamma.push_back(g);
        h.vectors.push_back(gather_to_root(x));
    }
    return h;
}

// A mode of the 3D body: harmonic h's k-th pair turned by `phase` (0, or
// pi / 2n for the second member of a pair).
struct Pick {
    double lambda;
    int h, k;
    double phase;
};

std::vector<Pick> merged_picks(const std::vector<HarmonicModes>& harmonics) {
    std::vector<Pick> picks;
    for (size_t h = 0; h < harmonics.size(); ++h)
        for (size_t k = 0; k < harmonics[h].eigenvalues.size(); ++k) {
            const int n = harmonics[h].n;
            picks.push_back({harmonics[h].eigenvalues[k], static_cast<int>(h), static_cast<int>(k), 0.0});
            if (n > 0) picks.push_back({harmonics[h].eigenvalues[k], static_cast<int>(h), static_cast<int>(k), M_PI / (2 * n)});
        }
    std::stable_sort(picks.begin(), picks.end(), [](const Pick& a, const Pick& b) { return a.lambda < b.lambda; });
    return picks;
}

// The n_modes-th lowest 3D eigenvalue so far (pairs counted twice), or none yet.
std::optional<double> band_edge(const std::vector<HarmonicModes>& harmonics, int n_modes) {
    const std::vector<Pick> picks = merged_picks(harmonics);
    if (static_cast<int>(picks.size()) < n_modes) return std::nullopt;
    return picks[n_modes - 1].lambda;
}

// The displacement of every node of the revolved mesh (and the frame nodes
// after them) for one pick: the cos family turned by `phase`, cos n(theta -
// phase) = cos n phase cos n theta + sin n phase sin n theta.
std::vector<double> revolved_shape(const RevolvedMesh& revolved, const HarmonicModes& h, int k, double phase,
                                   const std::vector<int>& frame_nodes) {
    if (phase == 0) return revolved_field(revolved, h.dofs, h.n, h.vectors[k], {}, frame_nodes);
    std::vector<double> a = h.vectors[k], b = h.vectors[k];
    for (double& v : a) v *= std::cos(h.n * phase);
    for (double& v : b) v *= std::sin(h.n * phase);
    return revolved_field(revolved, h.dofs, h.n, a, b, frame_nodes);
}

std::string harmonics_text(const std::vector<HarmonicModes>& harmonics) {
    std::string text;
    for (const HarmonicModes& h : harmonics) {
        text += (text.empty() ? "" : "; ") + std::string("n=") + std::to_string(h.n) + ": " +
                std::to_string(h.dofs.n_dofs) + " DOFs, ";
        if (h.solved)
            text += std::to_string(h.eigenvalues.size()) + " modes, " +
                    std::to_string(h.verification.negative_pivots_at_shift) + " eigenvalues below " +
                    significant(std::sqrt(std::max(h.verification.check_shift, 0.0)) / (2 * M_PI)) + " Hz";
        else
            text += "0 eigenvalues below the band edge (lowest " +
                    significant(std::sqrt(std::max(h.lowest, 0.0)) / (2 * M_PI)) + " Hz)";
    }
    return text;
}

Verification merged_verification(const std::vector<HarmonicModes>& harmonics) {
    Verification v;
    v.complete = true;
    v.check_shift = 1e300;
    for (const HarmonicModes& h : harmonics) {
        if (!h.solved) continue;  // counted: none below the edge
        const long multiplicity = h.n == 0 ? 1 : 2;
        v.max_relative_residual = std::max(v.max_relative_residual, h.verification.max_relative_residual);
        v.max_orthonormality_error = std::max(v.max_orthonormality_error, h.verification.max_orthonormality_error);
        v.check_shift = std::min(v.check_shift, h.verification.check_shift);
        v.negative_pivots_at_shift += multiplicity * h.verification.negative_pivots_at_shift;
        v.modes_below_shift += multiplicity * h.verification.modes_below_shift;
        v.eigenvalues_below_band += multiplicity * h.verification.eigenvalues_below_band;
        v.complete = v.complete && h.verification.complete;
    }
    return v;
}

// Why the search passed kMaxHarmonic, and what to change.
std::string beyond_last_harmonic(const Scene& scene, const SolveRequest& request) {
    const std::string wanted =
        request.lambda_max ? "the band's upper edge " + significant(std::sqrt(*request.lambda_max) / (2 * M_PI)) + " Hz"
                           : "the lowest [analysis] modes = " + std::to_string(scene.analysis.n_modes);
    return "every wave number up to n = " + std::to_string(kMaxHarmonic) + " has modes below " + wanted +
           ": the request reaches the cross-section's high ring modes; " +
           (request.lambda_max ? "lower the band's upper edge" : "ask for fewer modes");
}

// Harmonics n = 0, 1, 2, ... as walk_harmonics says (models/harmonic/
// harmonic_search.hpp), each solved below the band edge. Fills the model's
// mass and the timings.
std::vector<HarmonicModes> solve_harmonics(const Scene& scene, const SectionMesh& section,
                                           const std::vector<PartMaterial>& materials, SolveRequest request,
                                           const Printer& say, LevelModes& out) {
    const bool band = request.lambda_max.has_value();
    std::vector<HarmonicModes> harmonics;
    const auto visit = [&](int n) -> HarmonicVisit {
        Stopwatch lap;
        HarmonicSystem system = assemble_harmonic(scene, section, materials, n);
        if (n == 0) out.info.mass_kg = system.operators.model_mass;
        out.timing.assemble += lap.lap();
        const std::string line = "      n = " + std::to_string(n) + ": " + std::to_string(system.dofs.n_dofs) + " DOFs, ";
        const std::optional<double> edge = band ? request.lambda_max : band_edge(harmonics, scene.analysis.n_modes);
        if (n >= 2 && edge) {
            // Sylvester's count says how many of this harmonic's modes lie below the edge.
            const long below = count_eigenvalues_below(system.operators, *edge * (1 + 1e-9));
            if (below == 0) {
                HarmonicModes empty;
                empty.n = n;
                empty.dofs = system.dofs;
                empty.lowest = lowest_eigenvalue(system.operators, request);
                out.timing.factor_and_solve += lap.lap();
                say(line + "no mode below the band edge (lowest " +
                    significant(std::sqrt(std::max(empty.lowest, 0.0)) / (2 * M_PI)) + " Hz)");
                harmonics.push_back(std::move(empty));
                return {false, harmonics.back().lowest};
            }
            if (!band) request.n_modes = static_cast<int>(below);
        } else if (!band) {
            // n = 0 once; pairs (n >= 1) count twice.
            request.n_modes = n == 0 ? scene.analysis.n_modes : (scene.analysis.n_modes + 1) / 2;
        }
        HarmonicModes h = solve_harmonic(scene, system, section, request);
        out.timing.factor_and_solve += lap.lap();
        say(line + std::to_string(h.eigenvalues.size()) + " modes" +
            (h.eigenvalues.empty() ? std::string()
                                   : " from " + significant(std::sqrt(std::max(h.eigenvalues.front(), 0.0)) / (2 * M_PI)) + " Hz") +
            (h.verification.complete ? "" : " (INCOMPLETE)"));
        harmonics.push_back(std::move(h));
        return {true, 0};
    };
    walk_harmonics(visit, [&] { return beyond_last_harmonic(scene, request); });
    return harmonics;
}

ModelInfo harmonic_model_info(const Scene& scene, const SectionMesh& section,
                              const std::vector<HarmonicModes>& harmonics, double mass_kg) {
    ModelInfo info;
    info.level = ModelChoice::harmonic;
    info.element = "quad8";
    for (const HarmonicModes& h : harmonics) info.n_dofs = std::max<long>(info.n_dofs, h.dofs.n_dofs);
    info.n_nodes = section.n_nodes();
    info.n_elements = section.n_cells();
    for (const auto& [name, nodes] : section.node_groups)
        if (name.rfind("clamp_", 0) == 0) info.n_eliminated_nodes += static_cast<long>(nodes.size());
    info.mass_kg = mass_kg;
    info.expected_mass_kg = scene.mass_from_dimensions();
    info.mesh_source = "generated section";
    info.harmonics = harmonics_text(harmonics);
    return info;
}

// The lowest modes (a pair never cut in half) or the band's, in frequency
// order, each shown on the revolved mesh and named there.
std::vector<Mode> named_modes(const Scene& scene, const SolveRequest& request,
                              const std::vector<HarmonicModes>& harmonics, const RevolvedMesh& revolved) {
    const bool root = mpi_rank() == 0, band = request.lambda_max.has_value();
    const std::vector<int> frame_nodes = frame_nodes_of(scene, revolved.mesh);
    const ModeClassifier classifier(revolved.mesh, roll_nodes(revolved.mesh), body_held(scene));
    const std::optional<ModeSignatureSampler> signature =
        root ? std::optional<ModeSignatureSampler>(std::in_place, revolved.mesh) : std::nullopt;
    std::vector<Mode> modes;
    for (const Pick& pick : merged_picks(harmonics)) {
        const HarmonicModes& h = harmonics[pick.h];
        const bool second_of_pair = h.n > 0 && pick.phase > 0;
        if (!band && static_cast<int>(modes.size()) >= scene.analysis.n_modes && !second_of_pair) break;
        if (!in_band(pick.lambda, request)) continue;
        Mode mode = numbered_mode(static_cast<int>(modes.size()) + 1, pick.lambda, h.residuals[pick.k]);
        if (root) {
            const auto& g = h.gamma[pick.k];
            if (h.n == 1)  // sideways: the pair's first member along x, the second (turned by 90°) along y
                (pick.phase == 0 ? mode.effective_mass.x : mode.effective_mass.y) = g[0] * g[0];
            if (h.n == 0) {
                mode.effective_mass.z = g[1] * g[1];
                mode.effective_mass.rz = g[2] * g[2];
            }
            mode.shape = revolved_shape(revolved, h, pick.k, pick.phase, frame_nodes);
            mode.label = classifier.classify(mode.shape, pick.lambda, request.lambda_scale);
            mode.signature = (*signature)(mode.shape);
        }
        modes.push_back(std::move(mode));
    }
    return modes;
}

}  // namespace

LevelModes HarmonicLevel::solve(const Scene& scene, const Printer& say) {
    Stopwatch stage;
    LevelModes out;
    require_axisymmetric(scene);

    // 2. Mesh: the r–z section in quad8 cells (and its revolution, for showing the modes).
    say("[2/7] meshing the r-z section");
    // The counts and why (issue 33, 12): in the output and, as an assumption, in the summary.
    if (const auto rule = mesh_rule_text(scene)) {
        say("      " + *rule);
        out.assumptions.push_back(*rule);
    }
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    revolved_ = revolve_section(section, std::min(scene.mesh.n_around, kMaxDisplayAround));
    add_frame_nodes(scene, revolved_->mesh);  // as the solid has them, for the frame's motion in the shapes
    const std::vector<PartMaterial> materials = part_materials(scene, section.part_names, "generated section");
    out.timing.mesh = stage.lap();

    // 3-5. Per wave number n: assemble, solve, verify, prove complete.
    // Steps 3 and 4 alternate per n; the lines say what each is (the solid's numbering).
    say("[3/7] " + std::to_string(section.n_cells()) + " quad8 cells, " + std::to_string(section.n_nodes()) +
        " nodes: stiffness and mass assembled per wave number n");
    say(std::string("[4/7] solving one eigenproblem per wave number n (SLEPc Krylov-Schur, shift-and-invert with ") +
        shift_invert_factor_package(PETSC_COMM_WORLD) + "; MUMPS LDL^T for the counts)");
    const SolveRequest request = solve_request(scene);
    say(shift_scale_text(scene));
    const std::vector<HarmonicModes> harmonics = solve_harmonics(scene, section, materials, request, say, out);
    out.verification = merged_verification(harmonics);
    out.info = harmonic_model_info(scene, section, harmonics, out.info.mass_kg);
    stage.lap();

    // 6. Name every mode (on the revolved mesh, with the solid's classifier) and its effective masses.
    say("[5/7] classifying the modes");
    out.modes = named_modes(scene, request, harmonics, *revolved_);
    out.timing.classify = stage.lap();
    return out;
}

LevelShapes HarmonicLevel::shapes() const { return {&revolved_->mesh}; }

}  // namespace coremodal
