// `coremodal study CASE.toml [--output DIR]`: the case's [study] table run
// point by point, modes tracked by MAC, results in one folder (docs/how-to/studies.md).
#include "analyses/study/study.hpp"
#include "analyses/study/study_workers.hpp"
#include "app/commands.hpp"
#include "common/format.hpp"
#include "common/petsc_handle.hpp"
#include "common/warnings.hpp"
#include "output/results_folder.hpp"
#include "output/study_report.hpp"
#include "output/text_file.hpp"

#include <iostream>

namespace coremodal {
namespace {

struct StudyCommandOptions : SweepCommandOptions {
    // A worker child of a study (analyses/study/study_workers.hpp): hidden options.
    int worker_point = -1;
    std::string worker_table = "study", worker_output;
};

std::optional<std::string> mesh_option(const std::string& mesh) {
    return mesh.empty() ? std::nullopt : std::optional<std::string>(mesh);
}

int run_study_command(const StudyCommandOptions& o) {
    if (!o.worker_output.empty()) {
        const StudyPoint p = run_worker_point({o.case_file, o.worker_table, mesh_option(o.mesh), o.model, o.worker_point});
        if (mpi_rank() == 0) write_text_file(o.worker_output, point_record(p));
        return 0;
    }
    const bool root = mpi_rank() == 0;
    const CaseSweep sweep = CaseSweep::read(o.case_file, "study", mesh_option(o.mesh)).with_model(o.model);
    print_warnings(sweep.warnings());
    const std::filesystem::path out_dir = results_path(o.output, sweep.case_name(), "-study");
    claim_output(out_dir, o.force);
    StudyResult result = run_and_track(sweep, "study", out_dir, o.quiet, o.jobs);
    if (!root) return 0;

    ResultsFolder folder(out_dir, o.force);
    const std::filesystem::path& dir = folder.dir();
    const StudyFiles files = write_study_files(dir, sweep, result, "study", !o.no_plots);
    if (!files.plot_problem.empty() && !o.no_plots)
        std::cerr << "coremodal: warning: plots not drawn: " << files.plot_problem
                  << "; study.csv and report.md are complete (draw the plots later with "
                     "python3 -m coremodal study-plot DIR)" << std::endl;
    write_text_file(dir / "report.md", study_report_markdown(sweep, result, files.pngs, files.plot_problem));
    folder.commit();

    const int failed = result.n_failed();
    if (!o.quiet) std::cout << study_crossings_console(sweep, result);
    std::cout << "study: " << sweep.n_points() - failed << " of " << sweep.n_points() << " points ok in "
              << significant(result.time_s) << " s; " << out_dir.string() << "/report.md" << std::endl;
    if (failed) std::cerr << "coremodal: " << failed << " point(s) failed; see report.md" << std::endl;
    return failed ? 1 : 0;
}

}  // namespace

Command add_study_command(CLI::App& app) {
    auto o = std::make_shared<StudyCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "study", "Run the case's [study] table: every point of a grid of case-file values, the modes tracked from "
                 "point to point by MAC; study.csv, plots and report.md");
    add_sweep_options(cmd, *o, "study", ", e.g. cases/06-study-safe-speed.toml");
    cmd->add_option("--worker-point", o->worker_point)->group("");  // a study's child process
    cmd->add_option("--worker-table", o->worker_table)->group("");
    cmd->add_option("--worker-output", o->worker_output)->group("");
    cmd->footer("Exit status 0 when every point ran, 1 when any failed (its error is in report.md and study.csv) "
                "or the input is wrong. The [study] table: docs/how-to/studies.md.");
    return {cmd, [o] { return run_study_command(*o); }, true};
}

}  // namespace coremodal
