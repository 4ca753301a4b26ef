// run_case reads like the method section of a paper: numbered steps, each one
// stage of the pipeline (DESIGN.md), the same for every model level.
#include "analyses/run/run.hpp"

#include "analyses/run/rigid_comparison.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"
#include "common/warnings.hpp"
#include "models/choose.hpp"
#include "modes/verification_check.hpp"
#include "scene/case_file.hpp"
#include "scene/mesh_levels.hpp"

#include <filesystem>
#include <iostream>
#include <memory>

namespace coremodal {
namespace {

// "[k/N]" of a level with N steps.
std::string step(int k, const ModelLevel& level) {
    return "[" + std::to_string(k) + "/" + std::to_string(level.steps()) + "]";
}

// Steps 2–6 at the scene's level, and the rigid-mode check of a free scene.
// The report keeps the case reader's warnings (printed when the file was
// read) and adds the level's.
RunReport level_report(Scene scene, ModelLevel& level, const Printer& say) {
    RunReport report;
    report.mpi_ranks = mpi_size();
    report.warnings = scene.warnings;
    report.scene = std::move(scene);
    LevelModes solved = level.solve(report.scene, say);
    report.model = std::move(solved.info);
    report.modes.modes = std::move(solved.modes);
    report.modes.verification = solved.verification;
    report.timing_s = solved.timing;
    report.warnings.insert(report.warnings.end(), solved.warnings.begin(), solved.warnings.end());
    report.scene.assumptions.insert(report.scene.assumptions.end(), solved.assumptions.begin(),
                                    solved.assumptions.end());
    check_rigid_modes(report);
    return report;
}

// The end of step 6: modes that are not verified (a residual not finite or
// too large, an incomplete count, a mass that does not match the
// dimensions) end the run, or with keep_going become its warnings.
void require_verified_report(RunReport& report, bool keep_going) {
    std::vector<std::string> failures =
        verification_failures(report.modes.modes, report.modes.verification, report.scene.analysis.tolerance);
    if (!report.scene.mesh.file)
        if (const auto mass = mass_mismatch(report.model.mass_kg, report.model.expected_mass_kg))
            failures.push_back(*mass);
    for (const std::string& w : require_verified("the modes of " + report.scene.name + " (" + to_string(report.scene.model) +
                                                     " level)",
                                                 failures, keep_going))
        warn_about_model(report.scene.name, w, report.warnings);
}

// Step 7: beam theory, the chuck factor, the rigid-clamp variant.
void compare(RunReport& report, const ModelLevel& level, const RunOptions& options, const Printer& say) {
    const Scene& scene = report.scene;
    Stopwatch stage;
    say(step(level.steps() - 1, level) + " comparing with beam theory");
    report.beam = compare_with_beam(scene, report.modes.modes);
    if (scene.supports.kind != SupportKind::chucks) return;
    if (options.chuck_factor_by_fe) say("      chuck factor: the free-free roll over the free span (FE and beam)");
    report.chuck = chuck_factor(scene, report.beam.fe_first_bending_hz, options.chuck_factor_by_fe);
    report.timing_s.chuck_factor = stage.lap();
    if (options.compare_rigid) {
        say("      the same scene on rigid clamps over the expanding elements");
        const RunReport rigid = analyse_derived_scene(rigid_clamp_variant(scene));
        report.rigid_comparison = pair_by_label(report.modes.modes, rigid.modes.modes);
    }
}

}  // namespace

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

RunReport run_scene(Scene scene, const RunOptions& options) {
    scene.model = chosen_level(scene);  // "auto" resolved, for the summary and the derived scenes
    const std::unique_ptr<ModelLevel> level = make_model_level(scene);
    return run_scene(std::move(scene), options, *level);
}

RunReport run_scene(Scene scene, const RunOptions& options, ModelLevel& level) {
    scene.model = chosen_level(scene);
    const Printer say{mpi_rank() == 0 && !options.quiet};
    Stopwatch total;
    RunReport report = level_report(std::move(scene), level, say);  // 2-6
    require_verified_report(report, options.keep_going);
    compare(report, level, options, say);                             // 7
    double peak = peak_memory_mb();
    MPI_Allreduce(&peak, &report.peak_memory_mb, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    report.timing_s.total = total.seconds();
    if (options.write) options.write(report, level, options);  // 8
    return report;
}

RunReport analyse_derived_scene(Scene scene) {
    scene.model = chosen_level(scene);
    const std::unique_ptr<ModelLevel> level = make_model_level(scene);
    RunReport report = level_report(std::move(scene), *level, Printer{false});
    require_verified_report(report, false);
    report.beam = compare_with_beam(report.scene, report.modes.modes);
    return report;
}

}  // namespace coremodal
