// `coremodal response CASE.toml [--output DIR] [--model beam] [--mesh LEVEL] [--no-plots]`:
// the mid-span vibration of a spinning roll against web speed from its
// damping and excitation ([damping], [excitation], [response]), the
// resonance peaks and the safe web speed from the amplitude limit beside
// I-5 (docs/how-to/response.md). `coremodal run` on a case with [response] comes
// here too. At the beam level (Eigen only), the harmonic level (the r-z
// section) or the solid level (bodies of revolution; PETSc and SLEPc for
// their modes at rest).
#include "analyses/response/response.hpp"
#include "app/folder_case.hpp"
#include "common/error.hpp"
#include "output/response_report.hpp"
#include "scene/response_spec.hpp"

#include <memory>

namespace coremodal {

int run_response_case(const FolderCaseOptions& o) {
    require_one_process(o, "a forced response");
    ResponseCase c = parse_response_case(o.case_file);
    Scene& scene = c.scene;
    apply_level_options(o, scene);
    if (!c.response)
        throw InputError(o.case_file + ": no [response] table; expected [damping], [excitation] and [response] with "
                                       "web_speeds = [\"5 m/s\", \"20 m/s\"] and points (docs/how-to/response.md)");
    require_response_level(scene);
    const std::filesystem::path out_dir = prepare_folder_case(o, scene, "-response");
    const ResponseSetup& setup = *c.response;
    const ResponseResult result = run_forced_response(scene, setup);
    return write_folder_case(
        o, out_dir,
        {[&](const std::filesystem::path& dir) { write_response_tables(dir, scene, setup, result); },
         "response-plot", "response.png",  // python/coremodal/response_plot.py
         [&](const std::vector<std::string>& pngs, const std::string& problem) {
             return response_report_markdown(scene, setup, result, pngs, problem);
         },
         response_console_summary(scene, result)});
}

Command add_response_command(CLI::App& app) {
    auto o = std::make_shared<FolderCaseOptions>();
    CLI::App* cmd = app.add_subcommand(
        "response", "A spinning roll's forced response ([damping], [excitation], [response]): mid-span amplitude "
                    "against web speed, resonance peaks, the safe web speed from the amplitude limit beside I-5; "
                    "response.csv, response.png, report.md (beam, harmonic or solid level)");
    add_folder_case_options(cmd, *o, "case file (TOML) with a [response] table, e.g. cases/13-rest-roll-response-150x15.8-4320.toml",
                            "-response", "response.png");
    cmd->footer("Exit status 0 on success, 1 when the input is wrong (nothing is written then). "
                "The tables: docs/how-to/response.md.");
    return {cmd, [o] { return run_response_case(*o); }, true};
}

}  // namespace coremodal
