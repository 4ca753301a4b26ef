// `coremodal response CASE.toml [--output DIR] [--model beam] [--no-plots]`:
// the mid-span vibration of a spinning roll against web speed from its
// damping and excitation ([damping], [excitation], [response]), the
// resonance peaks and the safe web speed from the amplitude limit beside
// I-5 (docs/response.md). `coremodal run` on a case with [response] comes
// here too. Beam level, Eigen only: no mesh, no PETSc.
#include "analyses/response/response.hpp"
#include "app/commands.hpp"
#include "app/folder_picture.hpp"
#include "app/response_run.hpp"
#include "common/error.hpp"
#include "output/response_report.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"
#include "scene/response_spec.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace coremodal {
namespace {

// The picture the python package draws (python/coremodal/response_plot.py).
constexpr const char* kResponsePng = "response.png";

struct ResponseOptions {
    std::string case_file, output, model;
    bool quiet = false, no_plots = false, force = false;
};

}  // namespace

int run_response_case(const std::string& case_file, const std::string& model, const std::string& output, bool force,
                      bool no_plots, bool quiet) {
    ResponseCase c = parse_response_case(case_file);
    Scene& scene = c.scene;
    if (!model.empty()) scene.model = model;
    if (!c.response)
        throw InputError(case_file + ": no [response] table; expected [damping], [excitation] and [response] with "
                                     "web_speeds = [\"5 m/s\", \"20 m/s\"] and points (docs/response.md)");
    if (scene.model != "beam")
        throw InputError(case_file + ": [response] is simulated at the beam level only so far (model = \"" + scene.model +
                         "\"); expected model = \"beam\" or --model beam (docs/response.md)");
    const std::filesystem::path out_dir =
        output.empty() ? std::filesystem::path("results") / (scene.name + "-response") : std::filesystem::path(output);
    prepare_output(out_dir, force);  // refused before any work, never over the user's files
    for (const std::string& w : scene.warnings) std::cerr << "coremodal: warning: " << w << std::endl;
    const ResponseResult result = run_forced_response(scene, *c.response);

    ResultsFolder folder(out_dir, force);
    const std::filesystem::path& dir = folder.dir();
    write_response_tables(dir, scene, *c.response, result);
    const FolderPicture picture = draw_folder_picture("response-plot", dir, kResponsePng, no_plots);
    write_text_file(dir / "report.md", response_report_markdown(scene, *c.response, result, picture.pngs, picture.problem));
    folder.commit();
    if (!quiet) std::cout << response_console_summary(scene, result);
    std::cout << "  results: " << out_dir.string() << "/report.md" << std::endl;
    return 0;
}

Command add_response_command(CLI::App& app) {
    auto o = std::make_shared<ResponseOptions>();
    CLI::App* cmd = app.add_subcommand(
        "response", "A spinning roll's forced response ([damping], [excitation], [response]): mid-span amplitude "
                    "against web speed, resonance peaks, the safe web speed from the amplitude limit beside I-5; "
                    "response.csv, response.png, report.md (beam level)");
    cmd->add_option("case", o->case_file, "case file (TOML) with a [response] table, e.g. cases/13-rest-roll-response.toml")
        ->required();
    add_results_options(cmd, o->output, o->force, "-response");
    add_model_option(cmd, o->model);
    cmd->add_flag("-q,--quiet", o->quiet, "print only where the results are");
    cmd->add_flag("--no-plots", o->no_plots, "do not run python3 for response.png");
    cmd->footer("Exit status 0 on success, 1 when the input is wrong (nothing is written then). "
                "The tables: docs/response.md.");
    return {cmd, [o] { return run_response_case(o->case_file, o->model, o->output, o->force, o->no_plots, o->quiet); },
            false};
}

}  // namespace coremodal
