// `coremodal fit MEASUREMENTS.toml [--output DIR]`: case-file parameters
// fitted to measured frequencies (docs/how-to/calibration.md, "Fitting the model to
// measured frequencies"); fit.toml, report.md and the calibrated case files.
#include "analyses/fit/fit.hpp"
#include "app/commands.hpp"
#include "common/petsc_handle.hpp"
#include "output/fit_report.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"

#include <filesystem>
#include <iostream>

namespace coremodal {
namespace {

struct FitCommandOptions {
    std::string measurements, output;
    bool force = false, quiet = false;
};

int run_fit_command(const FitCommandOptions& o) {
    const bool root = mpi_rank() == 0;
    const FitInput input = read_fit_input(o.measurements);
    const std::filesystem::path out_dir = results_path(o.output, std::filesystem::path(o.measurements).stem().string(), "-fit");
    claim_output(out_dir, o.force);
    const FitOutcome outcome = run_fit(input, [&](const std::string& line) {
        if (root && !o.quiet) std::cout << "  fit: " << line << std::endl;
    });
    if (!root) return 0;
    ResultsFolder folder(out_dir, o.force);
    const std::vector<std::string> files = write_fitted_cases(folder.dir(), outcome);
    write_text_file(folder.dir() / "fit.toml", fit_toml(input, outcome));
    write_text_file(folder.dir() / "report.md", fit_report_markdown(input, outcome, files));
    folder.commit();
    std::cout << fit_console(outcome) << "fit: " << out_dir.string() << "/report.md" << std::endl;
    return outcome.converged ? 0 : 1;
}

}  // namespace

Command add_fit_command(CLI::App& app) {
    auto o = std::make_shared<FitCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "fit", "Fit case-file parameters (any key a [study] can vary) to measured frequencies, matched by mode "
               "label; Levenberg-Marquardt in log-parameters with exact eigenvalue sensitivities");
    cmd->add_option("measurements", o->measurements, "measurements file (TOML): parameters and [[measurement]] tables")
        ->required();
    add_results_options(cmd, o->output, o->force, "-fit");
    cmd->add_flag("-q,--quiet", o->quiet, "no progress lines");
    add_unused_option(cmd, "--no-plots", false, "it draws no pictures");
    cmd->footer("Writes fit.toml, report.md and <case>-fitted.toml per case. Exit status 0 when the fit converged "
                "(warnings about parameters the data cannot separate are in report.md); 1 otherwise. "
                "docs/how-to/calibration.md.");
    return {cmd, [o] { return run_fit_command(*o); }, true};
}

}  // namespace coremodal
