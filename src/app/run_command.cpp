// `coremodal run CASE.toml`: the main job.
#include "analyses/limits/limits.hpp"
#include "analyses/run/run.hpp"
#include "app/commands.hpp"
#include "app/folder_case.hpp"
#include "common/petsc_handle.hpp"
#include "output/results_folder.hpp"
#include "output/run_writer.hpp"
#include "scene/case_file.hpp"
#include "scene/response_spec.hpp"
#include "scene/rotation_spec.hpp"

#include <iostream>

namespace coremodal {
namespace {

// The command line before it becomes RunOptions: "" stands for "not given".
struct RunLine {
    RunOptions options;
    std::string output, mesh_level, model;
    bool no_plots = false;
};

// The verdict line of `coremodal limits` for a roll in its stand (issue 36),
// also under -q; nothing for a free scene.
void print_stand_verdict(const std::string& case_file) {
    if (mpi_rank() != 0) return;
    if (const std::string line = stand_verdict_line(case_file); !line.empty()) std::cout << line << std::endl;
}

int run_command(RunLine& line) {
    RunOptions& options = line.options;
    options.plots = !line.no_plots;
    if (!line.mesh_level.empty()) options.mesh_level = line.mesh_level;
    if (!line.model.empty()) options.model = model_option(line.model);
    const auto output_of = [&](const std::string& case_name) { return results_path(line.output, case_name, ""); };
    // A forced response (docs/how-to/response.md) before a spinning scene's modes
    // (docs/theory/rotation.md): [response] includes the rotation.
    const auto folder_case = [&](const Scene& scene) {
        FolderCaseOptions o{options.case_file, output_of(scene.name).string(), line.model};
        o.mesh = line.mesh_level;
        o.quiet = options.quiet;
        o.no_plots = line.no_plots;
        o.force = options.force;
        o.keep_going = options.keep_going;
        return o;
    };
    const auto with_verdict = [&](int code) {
        if (code == 0) print_stand_verdict(options.case_file);
        return code;
    };
    if (const ResponseCase c = parse_response_case(options.case_file); c.response)
        return with_verdict(run_response_case(folder_case(c.scene)));
    if (const RotatingCase c = parse_rotating_case(options.case_file); c.rotation)
        return with_verdict(run_rotating_case(folder_case(c.scene)));
    // The results folder is checked before any work (its default needs the case's name).
    options.output_dir = output_of(parse_case_file(options.case_file).name).string();
    claim_output(*options.output_dir, options.force);
    options.write = write_run;
    run_case(options);
    return with_verdict(0);
}

}  // namespace

Command add_run_command(CLI::App& app) {
    auto line = std::make_shared<RunLine>();
    RunOptions& options = line->options;
    CLI::App* cmd = app.add_subcommand("run", "Compute, verify and name the modes of one case file");
    cmd->add_option("case", options.case_file, "case file (TOML), e.g. cases/02-clamped-76x15.toml")->required();
    add_results_options(cmd, line->output, options.force, "");
    add_mesh_option(cmd, line->mesh_level);
    add_model_option(cmd, line->model);
    cmd->add_flag("-q,--quiet", options.quiet, "no progress lines or tables");
    cmd->add_flag("--compare-rigid", options.compare_rigid,
                  "with elastic chucks: also run rigid clamps over the expanding elements and list both mode "
                  "tables side by side (rigid_vs_elastic.csv)");
    cmd->add_flag("--no-plots", line->no_plots, "do not run python3 for the pictures in report.md");
    cmd->add_flag("--keep-going", options.keep_going,
                  "write the results even when the modes fail their verification (a residual not finite or "
                  "above 1e-6, an incomplete count, a mass that does not match), marked as not verified; "
                  "otherwise such a run exits non-zero and writes nothing");
    cmd->footer("PETSc/SLEPc options (e.g. -eps_view, -st_pc_factor_mat_solver_type mumps) may be added; "
                "they override coremodal's solver defaults.\n"
                "-factor_precision single|double|auto: the 3D solid's one LDL^T factor at the predicted band edge "
                "in single precision (solves refined in double, count proven or taken in double) or double; auto "
                "(default) is double. The run says which it used and why (docs/reference/commands.md).");
    return {cmd, [line] { return run_command(*line); }, true};
}

}  // namespace coremodal
