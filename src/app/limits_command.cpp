// `coremodal limits CASE.toml [--speed V] [--output DIR] [--model beam] [-q]
// [--no-plots]`: how fast the rest roll may run in its stand as it unwinds, one
// verdict over the rest-roll diameters with the criterion that governs and its
// band (analyses/limits, docs/how-to/limits.md). The console ends with the verdict
// line, also under -q.
#include "analyses/fit/fit.hpp"
#include "analyses/limits/limits.hpp"
#include "app/folder_case.hpp"
#include "common/error.hpp"
#include "output/limits_report.hpp"
#include "scene/limits_spec.hpp"
#include "scene/traction_case.hpp"

#include <iostream>
#include <memory>

namespace coremodal {
namespace {

struct LimitsOptions {
    FolderCaseOptions folder;
    std::optional<double> speed_m_s;  // --speed, overrides [limits] web_speed
    std::string fit_file;             // --fit: measured frequencies that narrow the band
};

// --fit: the measurements fitted (`coremodal fit`), the case read with its
// fitted values. Throws InputError when the measurements do not name the case.
LimitsCase fitted_case(const LimitsOptions& o, std::optional<FitOutcome>& fit) {
    fit = run_fit(read_fit_input(o.fit_file));
    for (const FittedCase& f : fit->cases) {
        std::error_code ec;
        if (std::filesystem::equivalent(f.case_file, o.folder.case_file, ec))
            return parse_limits_case_text(f.calibrated_text, o.folder.case_file);
    }
    throw InputError("--fit " + o.fit_file + ": no [[measurement]] names " + o.folder.case_file +
                     "; expected case = the stand's case file (the measured first resonance of this roll in its "
                     "stand, docs/how-to/limits.md)");
}

int run_limits_case(const LimitsOptions& o) {
    std::optional<FitOutcome> fit;
    LimitsCase c = o.fit_file.empty() ? parse_limits_case(o.folder.case_file) : fitted_case(o, fit);
    Scene& scene = c.scene;
    require_one_process(o.folder, "the limits verdict");
    apply_level_options(o.folder, scene);
    LimitsRequest request;
    request.spec = c.limits.value_or(LimitsSpec{});
    request.target_web_speed_m_s = o.speed_m_s;
    request.fit = fit, request.fit_file = o.fit_file;
    // The web's first idler, when the stand scene names one (docs/how-to/traction.md).
    if (const std::optional<TractionCase> roller = read_traction_case(o.folder.case_file))
        request.traction = traction_slip_criterion(roller->spec);
    require_limits_scene(scene, request);  // before the folder: nothing written on bad input
    const std::filesystem::path out_dir = prepare_folder_case(o.folder, scene, "-limits");
    if (!o.folder.quiet) request.progress = [](const std::string& line) { std::cout << "  " << line << std::endl; };
    const LimitsResult result = verdict(scene, c.response, request);
    const int code =
        write_folder_case(o.folder, out_dir,
                          {[&](const std::filesystem::path& dir) { write_limits_tables(dir, scene, result); },
                           "limits-plot", "limits.png",  // python/coremodal/limits_plot.py
                           [&](const std::vector<std::string>& pngs, const std::string& problem) {
                               return limits_report_markdown(scene, result, pngs, problem);
                           },
                           limits_console_summary(scene, result)});
    std::cout << verdict_line(result) << std::endl;
    return code;
}

}  // namespace

Command add_limits_command(CLI::App& app) {
    auto o = std::make_shared<LimitsOptions>();
    CLI::App* cmd = app.add_subcommand("limits",
                                       "How fast may this roll run in this stand: every criterion "
                                       "(I-5, Koenig, the order-1/-2 critical "
                                       "speeds, the amplitude limit) over the rest-roll diameters "
                                       "down to the bare core, the one that "
                                       "governs, its band, and where to change the roll for a target "
                                       "speed; limits.csv, limits.png, "
                                       "report.md");
    add_folder_case_options(cmd, o->folder,
                            "case file (TOML) of a roll in its stand, e.g. "
                            "cases/16-limits-rotogravure-150x15.8-4320.toml",
                            "-limits", "limits.png");
    cmd->add_option("--speed", o->speed_m_s,
                    "target web speed in m/s (overrides [limits] web_speed): the "
                    "rest-roll diameter where the roll "
                    "must be changed, and the margin");
    cmd->add_option("--fit", o->fit_file,
                    "measurements file of `coremodal fit` naming this case (the roll's first resonance measured "
                    "in its stand): the verdict on the fitted case, the band's contact and E_z ranges narrowed "
                    "to the fit's uncertainty (docs/how-to/limits.md)")
        ->check(CLI::ExistingFile);
    cmd->footer(
        "Exit status 0 on success, 1 when the input is wrong (nothing is "
        "written then). docs/how-to/limits.md.");
    return {cmd, [o] { return run_limits_case(*o); }, true};
}

}  // namespace coremodal
