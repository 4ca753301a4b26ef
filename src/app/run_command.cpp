// `coremodal run CASE.toml`: the main job.
#include "app/commands.hpp"
#include "analyses/run/run.hpp"
#include "app/response_run.hpp"
#include "app/rotation_run.hpp"
#include "output/results_folder.hpp"
#include "scene/case_file.hpp"
#include "scene/response_spec.hpp"
#include "scene/rotation_spec.hpp"

namespace coremodal {

Command add_run_command(CLI::App& app) {
    auto options = std::make_shared<RunOptions>();
    auto output = std::make_shared<std::string>();
    auto mesh_level = std::make_shared<std::string>();
    auto model = std::make_shared<std::string>();
    auto no_plots = std::make_shared<bool>(false);
    CLI::App* cmd = app.add_subcommand("run", "Compute, verify and name the modes of one case file");
    cmd->add_option("case", options->case_file, "case file (TOML), e.g. cases/02-clamped-76x15.toml")->required();
    cmd->add_option("-o,--output", *output,
                    "results folder (default results/<case name>); replaces only an earlier coremodal result, "
                    "which is kept as <folder>.previous (docs/results.md)");
    cmd->add_flag("--force", options->force, "remove the earlier result at --output instead of keeping it as .previous");
    cmd->add_option("-m,--mesh", *mesh_level,
                    "mesh level for a generated mesh, overriding the case: coarse, default, fine, very_fine");
    add_model_option(cmd, *model);
    cmd->add_flag("-q,--quiet", options->quiet, "no progress lines or tables");
    cmd->add_flag("--compare-rigid", options->compare_rigid,
                  "with elastic chucks: also run rigid clamps over the expanding elements and list both mode "
                  "tables side by side (rigid_vs_elastic.csv)");
    cmd->add_flag("--no-plots", *no_plots, "do not run python3 for the pictures in report.md");
    cmd->footer("PETSc/SLEPc options (e.g. -eps_view, -st_pc_factor_mat_solver_type mumps) may be added; "
                "they override coremodal's solver defaults.");
    auto run = [options, output, mesh_level, model, no_plots] {
        options->plots = !*no_plots;
        if (!mesh_level->empty()) options->mesh_level = *mesh_level;
        if (!model->empty()) options->model = *model;
        // A forced response (docs/response.md) before a spinning scene's
        // modes: [response] includes the rotation.
        if (const ResponseCase c = parse_response_case(options->case_file); c.response)
            return run_response_case(options->case_file, *model, !output->empty() ? *output : "results/" + c.scene.name,
                                     options->force, !options->plots, options->quiet);
        // A spinning scene: its modes at its speed(s), docs/rotation.md.
        if (const RotatingCase c = parse_rotating_case(options->case_file); c.rotation)
            return run_rotating_case(options->case_file, *model, !output->empty() ? *output : "results/" + c.scene.name,
                                     options->force, !options->plots, options->quiet);
        // The results folder is checked before any work (its default needs
        // the case's name).
        options->output_dir = !output->empty() ? *output : "results/" + parse_case_file(options->case_file).name;
        prepare_output(*options->output_dir, options->force);
        run_case(*options);
        return 0;
    };
    return {cmd, run, true};
}

}  // namespace coremodal
