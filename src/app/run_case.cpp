// run_case reads like the method section of a paper: numbered steps, each one
// stage of the pipeline (DESIGN.md).
#include "app/run_case.hpp"

#include "app/rigid_comparison.hpp"
#include "app/run_beam.hpp"
#include "app/run_harmonic.hpp"
#include "app/run_steps.hpp"
#include "assembly/chuck_supports.hpp"
#include "assembly/petsc_system.hpp"
#include "beam/beam_theory.hpp"
#include "beam/eigenvalue_scale.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/heartbeat.hpp"
#include "common/stopwatch.hpp"
#include "common/warnings.hpp"
#include "eigensolve/modal_solver.hpp"
#include "geometry/tube_model.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "modes/classify.hpp"
#include "modes/mac.hpp"
#include "modes/mode_shapes.hpp"
#include "output/modes_h5.hpp"
#include "output/results_folder.hpp"
#include "output/run_markdown.hpp"
#include "output/run_pictures.hpp"
#include "output/summary.hpp"
#include "output/text_file.hpp"
#include "output/xdmf.hpp"
#include "scene/case_file.hpp"
#include "scene/mesh_levels.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

namespace coremodal {
namespace {

std::vector<std::string> clamp_group_names(const Scene& scene) {
    std::vector<std::string> names;
    for (const auto& c : scene.supports.clamps) names.push_back("clamp_" + c.name);
    return names;
}

std::vector<std::string> chuck_group_names(const Scene& scene) {
    std::vector<std::string> names;
    for (const auto& c : scene.supports.chucks)
        for (const char* g : {"interface_%_core", "interface_%_chuck", "bearing_%"}) {
            std::string name = g;
            name.replace(name.find('%'), 1, c.name);
            names.push_back(name);
        }
    return names;
}

// Step 2: the mesh, generated from the scene's section or read from the user's file.
Mesh make_mesh(const Scene& scene) {
    GmshSession gmsh;
    if (scene.mesh.file && scene.supports.kind == SupportKind::chucks)
        throw InputError(scene.source_file + ": [mesh] file with [supports] type = \"chucks\": elastic chucks are "
                         "built into the generated mesh (core and chuck nodes must face each other); expected "
                         "no [mesh] file, or rigid clamps with a user mesh");
    if (scene.mesh.file) {
        Mesh mesh = read_msh_file(*scene.mesh.file);
        std::vector<std::string> parts = {"core"};
        if (scene.rest_paper) parts.push_back("rest_paper");
        require_groups(mesh, parts, clamp_group_names(scene), *scene.mesh.file,
                       scene.supports.kind == SupportKind::clamped ? "[supports] type = \"clamped\"" : "the scene");
        return mesh;
    }
    build_tube_model(make_tube_section(scene), scene.supports.clamps, scene.mesh.element);
    Mesh mesh = read_current_gmsh_mesh("generated mesh");
    require_groups(mesh, {"core"}, clamp_group_names(scene), "generated mesh", "the clamps");
    require_groups(mesh, {}, chuck_group_names(scene), "generated mesh", "the chucks");
    add_frame_nodes(scene, mesh);
    return mesh;
}

}  // namespace

std::vector<PartMaterial> part_materials(const Scene& scene, const std::vector<std::string>& part_names,
                                         const std::string& source) {
    std::vector<PartMaterial> materials;
    for (const auto& part : part_names) {
        const OrthotropicMaterial* m = nullptr;
        if (part == "core") m = &scene.core.material;
        if (part == "rest_paper" && scene.rest_paper) m = &scene.rest_paper->material;
        for (const auto& c : scene.supports.chucks)
            if (part == "chuck_" + c.name) m = &c.material;
        if (!m)
            throw InputError(source + ": mesh part '" + part + "' has no material in the case file; parts are "
                             "'core' and (with a [rest_paper] table) 'rest_paper'");
        materials.push_back({stiffness_cylindrical(*m), m->density});
    }
    return materials;
}

namespace {

std::vector<int> clamped_nodes(const Scene& scene, const Mesh& mesh) {
    std::set<int> nodes;
    for (const auto& name : clamp_group_names(scene))
        for (int n : mesh.node_groups.at(name)) nodes.insert(n);
    return {nodes.begin(), nodes.end()};
}

}  // namespace

namespace {

// Nodes held by the ground (eliminated, or on springs to the ground) and the
// links that join parts (spring layers, ties): for the "part not held" check.
struct Holding {
    std::vector<int> held;
    std::vector<std::vector<int>> links;
};

Holding holding(const std::vector<int>& eliminated, const ChuckSupports& chucks) {
    Holding h{eliminated, {}};
    for (const NodeTie& t : chucks.ties) h.links.push_back({t.node, t.master});
    for (const CouplingElement& e : chucks.couplings) h.links.push_back(e.nodes);
    h.held.insert(h.held.end(), chucks.grounded.begin(), chucks.grounded.end());
    return h;
}

// The free-free roll over the free span: the same core and rest paper, cut
// to L, no supports. Its first bending mode is smooth (no clamp edge), so
// it converges at h^4: the coarse level is within 0.1 % of the converged
// value (case 01: 133.46 against 133.36 Hz), far inside the uncertainty of
// any k, at a fraction of the scene's cost; finer scene meshes do not
// coarsen it further.
Scene free_span_scene(const Scene& scene, double span) {
    Scene free = scene;
    free.name = scene.name + "-free-span";
    free.core.length = span;
    free.supports = {};
    free.analysis = {};
    free.analysis.n_modes = 8;  // 6 rigid modes and the bending pair
    free.mesh.along_per_segment.clear();  // a ladder's counts are for the scene's segments, not the span's
    const MeshLevel& coarse = *find_mesh_level("coarse");
    free.mesh.n_wall = std::min(scene.mesh.n_wall, coarse.n_wall);
    free.mesh.n_rest_paper = std::min(scene.mesh.n_rest_paper, coarse.n_rest_paper);
    free.mesh.n_around = std::min(scene.mesh.n_around, coarse.n_around);
    free.mesh.n_along = std::min(
        static_cast<int>(std::lround(scene.mesh.n_along * span / scene.core.length)),
        elements_along(span, free.core.outer_diameter,
                       free.mesh.n_around, coarse.axial_aspect)
            .value_or(kMaxElementsAlong));
    free.mesh.n_along = std::max(free.mesh.n_along, kMinElementsAlong);
    return free;
}

}  // namespace

ChuckFactor chuck_factor(const Scene& scene, double f1, bool by_model) {
    const auto& chucks = scene.supports.chucks;
    ChuckFactor k;
    k.li_left_m = chucks.at(0).li();
    k.li_right_m = chucks.at(1).li();
    k.li_m = (k.li_left_m + k.li_right_m) / 2;
    k.free_span_m = scene.core.length - k.li_left_m - k.li_right_m;
    k.f1_hz = f1;
    if (by_model) {
        RunOptions quiet;
        quiet.quiet = true;
        quiet.write_results = false;
        k.f2_fe_hz = run_scene(free_span_scene(scene, k.free_span_m), quiet).beam.fe_first_bending_hz;
    }
    k.f2_beam_hz = timoshenko_bending_hz(beam_section(scene), k.free_span_m, BeamEnds::free_free, 1).at(0);
    k.chuck_factor = k.f2_fe_hz > 0 ? f1 / k.f2_fe_hz : 0;
    k.chuck_factor_beam = f1 / k.f2_beam_hz;
    return k;
}

namespace {

// In words, for the console, report.md and summary.json.
std::string why_no_bending_mode(const AnalysisSpec& analysis, const std::vector<Mode>& modes) {
    const long rigid = std::count_if(modes.begin(), modes.end(), [](const Mode& m) { return m.label.type == "rigid"; });
    if (analysis.f_max_hz) {
        const std::string band = "between " + significant(analysis.f_min_hz.value_or(0.0)) + " and " +
                                 significant(*analysis.f_max_hz) + " Hz";
        return modes.empty() ? "no modes " + band
                             : "no bending mode among the " + std::to_string(modes.size()) + " modes " + band +
                                   " (widen the band)";
    }
    return "no bending mode among the " + std::to_string(modes.size()) + " modes found (" + std::to_string(rigid) +
           " rigid); ask for more modes";
}

}  // namespace

BeamComparison compare_with_beam(const Scene& scene, const std::vector<Mode>& modes) {
    BeamComparison b;
    const BeamSection section = beam_section(scene);
    const bool free = scene.supports.kind == SupportKind::free;
    b.span_m = beam_span(scene);
    b.ends = free ? "free-free" : "clamped-clamped";
    b.euler_bernoulli_hz = euler_bernoulli_first_bending_hz(section, b.span_m);
    b.timoshenko_hz =
        timoshenko_bending_hz(section, b.span_m, free ? BeamEnds::free_free : BeamEnds::clamped_clamped, 1).at(0);
    for (const auto& m : modes)
        if (m.label.type == "bending") {
            b.fe_first_bending_hz = m.frequency_hz;
            b.fe_mode_index = m.index;
            b.fe_over_timoshenko = m.frequency_hz / b.timoshenko_hz;
            b.fe_over_euler_bernoulli = m.frequency_hz / b.euler_bernoulli_hz;
            return b;
        }
    b.fe_missing = why_no_bending_mode(scene.analysis, modes);
    return b;
}

namespace {

void write_results(const RunReport& report, const Mesh& mesh, const std::filesystem::path& dir, bool plots,
                   bool force) {
    ResultsFolder folder(dir, force);
    write_summary_json(folder.file("summary.json"), report);
    write_modes_csv(folder.file("modes.csv"), report);
    write_modes_h5(folder.file("modes.h5"), mesh, report.modes.modes, report.scene.name, scene_json(report.scene),
                   "coremodal " COREMODAL_VERSION);
    write_modes_xdmf(folder.file("modes.xdmf"), "modes.h5", mesh, report.modes.modes);
    if (!report.rigid_comparison.empty()) {
        std::ofstream csv(folder.file("rigid_vs_elastic.csv"));
        csv << side_by_side_csv(report.rigid_comparison);
        if (!csv) throw SolveError("cannot write " + folder.file("rigid_vs_elastic.csv"));
    }
    // The pictures read modes.h5, so they come last; the report says why
    // when there are none, and the run stays complete without them.
    const std::filesystem::path partial = std::filesystem::path(folder.file("modes.h5")).parent_path();
    const RunPictures pictures = draw_run_pictures(partial, report.modes.modes, plots);
    if (plots && !pictures.problem.empty())
        std::cerr << "coremodal: warning: no pictures in report.md: " << pictures.problem << std::endl;
    write_text_file(folder.file("report.md"), run_report_markdown(report, pictures));
    folder.commit();
}

}  // namespace

SolveRequest solve_request(const Scene& scene) {
    SolveRequest request;
    request.n_modes = scene.analysis.n_modes;
    if (scene.analysis.f_max_hz) {
        request.lambda_max = std::pow(2 * M_PI * *scene.analysis.f_max_hz, 2);
        request.lambda_min = std::pow(2 * M_PI * scene.analysis.f_min_hz.value_or(0.0), 2);
    }
    // The lowest of the closed-form estimates of every family of modes: the
    // right order for a long core, a ring and a disc alike (eigenvalue_scale.hpp).
    request.lambda_scale = elastic_eigenvalue_scale(scene, ModeFamilies::beam_and_section).lambda;
    request.tolerance = scene.analysis.tolerance;
    request.max_iterations = scene.analysis.max_iterations;
    return request;
}

std::string shift_scale_text(const Scene& scene) {
    const EigenvalueEstimate scale = elastic_eigenvalue_scale(scene, ModeFamilies::beam_and_section);
    return "      shift from the scale of the first elastic mode: " + scale.family + " estimate, " +
           significant(std::sqrt(scale.lambda) / (2 * M_PI)) + " Hz";
}

void print_scene_warnings(const Scene& scene) { print_warnings(scene.warnings); }

RunReport run_case(const RunOptions& options) {
    // 1. Read and check the case file: every input error surfaces here.
    if (mpi_rank() == 0 && !options.quiet) std::cout << "  [1/7] reading " << options.case_file << std::endl;
    Scene scene = parse_case_file(options.case_file);
    print_scene_warnings(scene);
    if (options.mesh_level) apply_mesh_level(scene, *options.mesh_level);
    if (options.model) scene.model = *options.model;
    return run_scene(std::move(scene), options);
}

RunReport run_scene(Scene scene_in, const RunOptions& options) {
    // "auto": the cheapest level that represents the whole scene (DESIGN.md):
    // harmonic when the scene is a body of revolution, else the solid.
    if (scene_in.model == "auto") scene_in.model = why_not_axisymmetric(scene_in) ? "solid" : "harmonic";
    if (scene_in.model == "beam") return run_beam_scene(std::move(scene_in), options);  // app/run_beam.cpp
    if (scene_in.model == "harmonic") return run_harmonic_scene(std::move(scene_in), options);  // app/run_harmonic.cpp
    const bool root = mpi_rank() == 0;
    const Printer say{root && !options.quiet};
    Stopwatch total, stage;
    RunReport report = new_report(std::move(scene_in));
    const Scene& scene = report.scene;

    // 2. Mesh: the section extruded into quadratic hexahedra (or the user's mesh).
    say("[2/7] meshing" + (scene.mesh.file ? " (reading " + *scene.mesh.file + ")" : std::string()));
    const Mesh mesh = [&] {
        const Heartbeat beat("meshing", say);
        return make_mesh(scene);
    }();
    const std::string mesh_source = scene.mesh.file ? *scene.mesh.file : "generated mesh";
    report.timing_s.mesh = stage.lap();

    // 3. Degrees of freedom: clamped nodes (and shaft ends in rigid bearings)
    //    are eliminated; bonded core nodes take their chuck node's DOFs.
    const ChuckSupports chucks = chuck_supports(scene, mesh);
    std::vector<int> eliminated = clamped_nodes(scene, mesh);
    eliminated.insert(eliminated.end(), chucks.eliminated.begin(), chucks.eliminated.end());
    const DofMap dofs = make_dof_map(mesh.n_nodes(), eliminated, chucks.ties);
    report.model = {"solid3d",
                    cell_type_name(mesh.cell_type),
                    dofs.n_dofs,
                    mesh.n_nodes(),
                    mesh.n_cells(),
                    static_cast<long>(eliminated.size()),
                    0,
                    scene.mass_from_dimensions(),
                    mesh_source,
                    ""};
    const Holding held = holding(eliminated, chucks);
    for (const std::string& warning : unheld_parts(mesh, held.held, held.links)) {
        if (root) std::cerr << "coremodal: warning: " << mesh_source << ": " << warning << std::endl;
        report.warnings.push_back(warning);
    }
    say("      " + std::to_string(mesh.n_cells()) + " " + report.model.element + " cells, " +
        std::to_string(mesh.n_nodes()) + " nodes, " + std::to_string(dofs.n_dofs) + " DOFs (" +
        std::to_string(eliminated.size()) + " clamped nodes eliminated)");

    // 4. Assemble K and M.
    say("[3/7] assembling stiffness and mass");
    const OperatorSet system = [&] {
        const Heartbeat beat("assembling", say);
        return assemble_petsc(mesh, part_materials(scene, mesh.part_names, mesh_source), dofs, chucks.couplings);
    }();
    report.model.mass_kg = system.model_mass;
    report.timing_s.assemble = stage.lap();

    // 5. Solve, verify, prove complete. The scale of the first elastic
    //    eigenvalue sets the shift (and what counts as rigid).
    say(std::string("[4/7] solving the eigenproblem (SLEPc Krylov-Schur, shift-and-invert with ") +
        shift_invert_factor_package(PETSC_COMM_WORLD) + "; MUMPS LDL^T for the count)");
    const SolveRequest request = solve_request(scene);
    say(shift_scale_text(scene));
    // The solver's input errors (e.g. more modes than DOFs) are about the
    // case file's [analysis] table: name the file.
    SolvedModes solved = [&] {
        try {
            return solve_modes(system, request, say);
        } catch (const InputError& e) {
            throw InputError(scene.source_file + ": " + e.what());
        }
    }();
    report.modes.verification = solved.verification;
    report.timing_s.factor_and_solve = stage.lap();

    // 6. Name every mode and compute its effective masses.
    say("[5/7] classifying " + std::to_string(solved.eigenvalues.size()) + " modes");
    const ModeClassifier classifier(mesh, roll_nodes(mesh));
    const std::optional<ModeSignatureSampler> signature =
        root ? std::optional<ModeSignatureSampler>(std::in_place, mesh) : std::nullopt;
    const EffectiveMassCalculator effective_mass(system.M(), mesh, dofs);
    for (size_t i = 0; i < solved.eigenvalues.size(); ++i) {
        const double lambda = solved.eigenvalues[i];
        if (!in_band(lambda, request)) continue;  // computed from the bottom, below the band
        Mode mode;
        mode.index = static_cast<int>(report.modes.modes.size()) + 1;
        mode.eigenvalue = lambda;
        mode.frequency_hz = std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI);
        mode.relative_residual = solved.relative_residuals[i];
        mode.effective_mass = effective_mass(solved.vectors[i]);
        mode.shape = gather_node_displacements(solved.vectors[i], mesh, dofs);
        if (root) mode.label = classifier.classify(mode.shape, lambda, request.lambda_scale);
        if (root) mode.signature = (*signature)(mode.shape);
        report.modes.modes.push_back(std::move(mode));
    }
    report.timing_s.classify = stage.lap();

    finish_run(report, mesh, options, total, stage);
    return report;
}

void check_rigid_modes(const RunReport& report) {
    const Scene& s = report.scene;
    // A user mesh may hold parts that touch nothing (warned about: six rigid modes each).
    if (s.supports.kind != SupportKind::free || s.mesh.file || s.analysis.f_min_hz.value_or(0.0) > 0) return;
    const std::vector<Mode>& modes = report.modes.modes;
    const int expected = std::min<int>(kFreeBodyRigidModes, static_cast<int>(modes.size()));
    int rigid = 0, lowest_rigid = 0;
    for (size_t i = 0; i < modes.size(); ++i) {
        rigid += modes[i].label.type == "rigid";
        lowest_rigid += modes[i].label.type == "rigid" && static_cast<int>(i) < expected;
    }
    // Modes are named on rank 0 only: its verdict holds for every rank, so
    // that all stop together (a rank alone in a collective would wait forever).
    int ok = rigid == expected && lowest_rigid == expected;
    MPI_Bcast(&ok, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    MPI_Bcast(&rigid, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    if (ok) return;
    throw SolveError(s.source_file + ": the free scene's lowest modes should be its six rigid-body motions "
                     "(DOMAIN.md section 5), but " + std::to_string(rigid) + " of the lowest " +
                     std::to_string(modes.size()) + " are rigid: round-off in the stiffness matrix is as large as "
                     "the body's lowest elastic eigenvalues, so they cannot be told apart. A core " +
                     significant(s.core.length) + " m long and " + significant(s.core.outer_diameter) +
                     " m across is beyond what double precision resolves at this model level; expected a body at "
                     "least about a hundredth as long as its diameter");
}

void finish_run(RunReport& report, const Mesh& mesh, const RunOptions& options, const Stopwatch& total,
                Stopwatch& stage) {
    check_rigid_modes(report);
    const bool root = mpi_rank() == 0;
    const Printer say{root && !options.quiet};
    const Scene& scene = report.scene;
    const std::filesystem::path out_dir =
        options.output_dir ? std::filesystem::path(*options.output_dir) : std::filesystem::path("results") / scene.name;
    // 7. Compare with beam theory.
    say("[6/7] comparing with beam theory");
    report.beam = compare_with_beam(scene, report.modes.modes);
    if (scene.supports.kind == SupportKind::chucks) {
        if (options.chuck_factor_by_fe) say("      chuck factor: the free-free roll over the free span (FE and beam)");
        report.chuck = chuck_factor(scene, report.beam.fe_first_bending_hz, options.chuck_factor_by_fe);
        report.timing_s.chuck_factor = stage.lap();
    }
    if (options.compare_rigid && scene.supports.kind == SupportKind::chucks) {
        say("      the same scene on rigid clamps over the expanding elements");
        RunOptions quiet;
        quiet.quiet = true;
        quiet.write_results = false;
        const RunReport rigid = run_scene(rigid_clamp_variant(scene), quiet);
        report.rigid_comparison = pair_by_label(report.modes.modes, rigid.modes.modes);
    }

    double peak = peak_memory_mb();
    MPI_Allreduce(&peak, &report.peak_memory_mb, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    report.timing_s.total = total.seconds();

    // 8. Write: console table, then the results folder (complete or not at all).
    if (root && !options.quiet) {
        print_mode_table(std::cout, report);
        print_verification_and_beam(std::cout, report);
        if (!report.rigid_comparison.empty()) print_side_by_side(std::cout, report.rigid_comparison);
    }
    if (root && options.write_results) {
        say("[7/7] writing " + out_dir.string());
        write_results(report, mesh, out_dir, options.plots, options.force);
    }
}

}  // namespace coremodal
