// `coremodal campbell CASE.toml [--output DIR] [--model beam] [--mesh LEVEL] [--no-plots]`:
// the modes of a spinning scene ([rotation]) at every speed of its sweep,
// followed by MAC and labelled forward/backward whirl, with the critical
// speeds where the excitation lines f = k f_rot cross them (docs/how-to/campbell.md).
// `coremodal run` on a case with [rotation] comes here too (one speed: the
// modes at that speed). Beam level (Eigen only), harmonic and solid levels (SLEPc).
#include "analyses/campbell/campbell.hpp"
#include "app/folder_case.hpp"
#include "common/error.hpp"
#include "common/warnings.hpp"
#include "models/choose.hpp"
#include "modes/verification_check.hpp"
#include "output/campbell_report.hpp"
#include "scene/rotation_spec.hpp"

#include <memory>

namespace coremodal {

int run_rotating_case(const FolderCaseOptions& o) {
    require_one_process(o, "a Campbell sweep");
    ResponseCase rotating = parse_response_case(o.case_file);  // [damping] too (damped modes)
    Scene& scene = rotating.scene;
    apply_level_options(o, scene);
    if (!rotating.rotation)
        throw InputError(o.case_file + ": no [rotation] table; expected one with speed = \"1200 rpm\" or "
                                       "speeds = [\"0 rpm\", \"4000 rpm\"] and points (docs/how-to/campbell.md)");
    // "auto": the harmonic level for a body of revolution (models/choose), else the solid, which spins
    // the others in co-rotating coordinates (and refuses a chuck not expanded here, before any work).
    // The coupled-harmonic level has no spinning terms: where "auto" would pick it, the solid spins.
    // Asked for by name, require_spinning_level says why not.
    scene.model = chosen_spinning_level(scene);
    require_spinning_level(scene);
    const DampingSpec* damping = rotating.damping ? &*rotating.damping : nullptr;
    if (damping) require_campbell_damping(scene, *damping);
    const std::filesystem::path out_dir = prepare_folder_case(o, scene, "-campbell");
    const RotationSpec& rotation = *rotating.rotation;
    const CampbellResult result = run_campbell(scene, rotation, damping);
    // Every mode at every speed: its residual of the quadratic problem (the
    // counts are checked where each speed is solved).
    std::vector<std::string> failures;
    if (!(result.max_relative_residual <= kMaxVerifiedResidual))
        failures.push_back("the largest relative residual over the speeds is " +
                           std::to_string(result.max_relative_residual) + ", not a finite number at most " +
                           std::to_string(kMaxVerifiedResidual));
    if (result.damped && !(result.max_damped_residual <= kMaxVerifiedResidual))
        failures.push_back("the largest relative residual of a damped mode on the full damped set is " +
                           std::to_string(result.max_damped_residual) + ", not a finite number at most " +
                           std::to_string(kMaxVerifiedResidual));
    print_warnings(require_verified("the Campbell diagram of " + scene.name, failures, o.keep_going));
    return write_folder_case(
        o, out_dir,
        {[&](const std::filesystem::path& dir) { write_campbell_tables(dir, scene, rotation, result); },
         "campbell-plot", "campbell.png",  // python/coremodal/campbell_plot.py
         [&](const std::vector<std::string>& pngs, const std::string& problem) {
             return campbell_report_markdown(scene, result, pngs, problem);
         },
         campbell_console_summary(scene, result)});
}

Command add_campbell_command(CLI::App& app) {
    auto o = std::make_shared<FolderCaseOptions>();
    CLI::App* cmd = app.add_subcommand(
        "campbell", "A spinning scene ([rotation]): natural frequencies against rotation speed with forward and "
                    "backward whirl, the excitation lines and the critical speeds; campbell.csv, campbell.png, "
                    "report.md (beam, harmonic and solid levels)");
    add_folder_case_options(cmd, *o, "case file (TOML) with a [rotation] table, e.g. cases/12-rotation-tester-76x15.toml",
                            "-campbell", "campbell.png");
    cmd->add_flag("--keep-going", o->keep_going,
                  "write the results even when the modes fail their verification (a residual not finite or above "
                  "1e-6), marked as not verified; otherwise such a run exits non-zero and writes nothing");
    cmd->footer("Exit status 0 on success, 1 when the input is wrong (nothing is written then). "
                "The [rotation] table: docs/how-to/campbell.md.");
    // PETSc and SLEPc: the harmonic and solid levels solve with them (the beam level does not need them).
    return {cmd, [o] { return run_rotating_case(*o); }, true};
}

}  // namespace coremodal
