// `coremodal campbell CASE.toml [--output DIR] [--model beam] [--no-plots]`:
// the modes of a spinning scene ([rotation]) at every speed of its sweep,
// followed by MAC and labelled forward/backward whirl, with the critical
// speeds where the excitation lines f = k f_rot cross them (docs/rotation.md).
// `coremodal run` on a case with [rotation] comes here too (one speed: the
// modes at that speed). Beam level, Eigen only: no mesh, no PETSc.
#include "analyses/campbell/campbell.hpp"
#include "app/commands.hpp"
#include "app/folder_picture.hpp"
#include "app/rotation_run.hpp"
#include "models/choose.hpp"
#include "common/error.hpp"
#include "output/campbell_report.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"
#include "scene/rotation_spec.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace coremodal {
namespace {

// The picture the python package draws (python/coremodal/campbell_plot.py).
constexpr const char* kCampbellPng = "campbell.png";

struct CampbellOptions {
    std::string case_file, output, model;
    bool quiet = false, no_plots = false, force = false;
};

}  // namespace

int run_rotating_case(const std::string& case_file, const std::string& model, const std::string& output, bool force,
                      bool no_plots, bool quiet) {
    RotatingCase rotating = parse_rotating_case(case_file);
    Scene& scene = rotating.scene;
    if (!model.empty()) scene.model = model;
    if (!rotating.rotation)
        throw InputError(case_file + ": no [rotation] table; expected one with speed = \"1200 rpm\" or "
                                     "speeds = [\"0 rpm\", \"4000 rpm\"] and points (docs/rotation.md)");
    // "auto": the harmonic level for a body of revolution (models/choose), else the solid, which spins
    // bodies of revolution only (and refuses the others here, before any work).
    scene.model = chosen_level(scene);
    require_spinning_level(scene);
    const std::filesystem::path out_dir =
        output.empty() ? std::filesystem::path("results") / (scene.name + "-campbell") : std::filesystem::path(output);
    prepare_output(out_dir, force);  // refused before any work, never over the user's files
    for (const std::string& w : scene.warnings) std::cerr << "coremodal: warning: " << w << std::endl;
    const CampbellResult result = run_campbell(scene, *rotating.rotation);

    ResultsFolder folder(out_dir, force);
    const std::filesystem::path& dir = folder.dir();
    write_campbell_tables(dir, scene, *rotating.rotation, result);
    const FolderPicture picture = draw_folder_picture("campbell-plot", dir, kCampbellPng, no_plots);
    write_text_file(dir / "report.md", campbell_report_markdown(scene, result, picture.pngs, picture.problem));
    folder.commit();
    if (!quiet) std::cout << campbell_console_summary(scene, result);
    std::cout << "  results: " << out_dir.string() << "/report.md" << std::endl;
    return 0;
}

Command add_campbell_command(CLI::App& app) {
    auto o = std::make_shared<CampbellOptions>();
    CLI::App* cmd = app.add_subcommand(
        "campbell", "A spinning scene ([rotation]): natural frequencies against rotation speed with forward and "
                    "backward whirl, the excitation lines and the critical speeds; campbell.csv, campbell.png, "
                    "report.md (beam, harmonic and solid levels)");
    cmd->add_option("case", o->case_file, "case file (TOML) with a [rotation] table, e.g. cases/12-rotation-tester-76x15.toml")
        ->required();
    add_results_options(cmd, o->output, o->force, "-campbell");
    add_model_option(cmd, o->model);
    cmd->add_flag("-q,--quiet", o->quiet, "print only where the results are");
    cmd->add_flag("--no-plots", o->no_plots, "do not run python3 for campbell.png");
    cmd->footer("Exit status 0 on success, 1 when the input is wrong (nothing is written then). "
                "The [rotation] table: docs/rotation.md.");
    // PETSc and SLEPc: the harmonic level solves with them (the beam level does not need them).
    return {cmd, [o] { return run_rotating_case(o->case_file, o->model, o->output, o->force, o->no_plots, o->quiet); },
            true};
}

}  // namespace coremodal
