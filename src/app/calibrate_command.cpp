// `coremodal calibrate CASE.toml [--output DIR]`: the [calibration] sweep,
// the table of k, the fitted law and its check; calibration.toml for
// `coremodal beam --calibration` (docs/how-to/calibration.md).
#include "analyses/calibrate/calibrate.hpp"
#include "app/commands.hpp"
#include "common/petsc_handle.hpp"
#include "common/warnings.hpp"
#include "output/calibration_report.hpp"
#include "output/results_folder.hpp"
#include "output/study_report.hpp"
#include "output/text_file.hpp"

#include <iostream>

namespace coremodal {
namespace {

struct CalibrateOptions : SweepCommandOptions {};

int run_calibrate_command(const CalibrateOptions& o) {
    const bool root = mpi_rank() == 0;
    const CaseSweep sweep = CaseSweep::read(o.case_file, "calibration",
                                            o.mesh.empty() ? std::nullopt : std::optional<std::string>(o.mesh))
                                .with_model(o.model);
    print_warnings(sweep.warnings());
    const std::filesystem::path out_dir = results_path(o.output, sweep.case_name(), "-calibration");
    claim_output(out_dir, o.force);
    StudyResult result = run_and_track(sweep, "calibrate", out_dir, o.quiet, o.jobs);
    if (!root) return 0;
    const CalibrationOutcome outcome = calibrate_chuck_factor(sweep, result);

    ResultsFolder folder(out_dir, o.force);
    const std::filesystem::path& dir = folder.dir();
    write_calibration((dir / "calibration.toml").string(), outcome.calibration);
    write_text_file(dir / "calibration.csv", calibration_csv(sweep, outcome));
    const StudyFiles files = write_study_files(dir, sweep, result, "calibration", !o.no_plots);
    if (!files.plot_problem.empty() && !o.no_plots)
        std::cerr << "coremodal: warning: plots not drawn: " << files.plot_problem << std::endl;
    write_text_file(dir / "report.md",
                    calibration_report_markdown(sweep, result, outcome, files.pngs, files.plot_problem));
    folder.commit();

    const Calibration& c = outcome.calibration;
    std::cout << calibration_console(c, out_dir.string()) << std::flush;
    if (!c.passed)
        std::cerr << "coremodal: the calibration does not reproduce the FE f1 within the stated error; see "
                  << out_dir.string() << "/report.md" << std::endl;
    if (result.n_failed()) std::cerr << "coremodal: " << result.n_failed() << " point(s) failed; see report.md" << std::endl;
    return c.passed && !result.n_failed() ? 0 : 1;
}

}  // namespace

Command add_calibrate_command(CLI::App& app) {
    auto o = std::make_shared<CalibrateOptions>();
    CLI::App* cmd = app.add_subcommand(
        "calibrate", "Run the case's [calibration] table, tabulate the chuck factor k, fit it as a function of "
                     "dimensionless groups and check it on held-out points; writes calibration.toml for "
                     "`coremodal beam --calibration`");
    add_sweep_options(cmd, *o, "calibration");
    cmd->footer("Exit status 0 when every point ran and I-7 with the fitted k reproduces the FE f1 within "
                "[calibration] max_error on fitted and held-out points; 1 otherwise (the results are written "
                "either way). docs/how-to/calibration.md.");
    return {cmd, [o] { return run_calibrate_command(*o); }, true};
}

}  // namespace coremodal
