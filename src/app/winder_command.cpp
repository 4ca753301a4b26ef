// `coremodal winder WINDER.toml [--output DIR] [--no-plots] [--quiet]`: the
// two-drum winder of a [winder] case file, its modes as the rolls grow, the
// crossings of the rolls' rotation harmonics with the drum-dominated modes
// and the response at a drum's centre (docs/how-to/winder.md). Beam level, Eigen
// only: no mesh, no PETSc.
#include "app/commands.hpp"
#include "common/format.hpp"
#include "output/python_plots.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"
#include "output/winder_report.hpp"
#include "winder/winder_sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace coremodal {
namespace {

struct WinderOptions {
    std::string case_file, output;
    bool quiet = false, no_plots = false, force = false;
};

int run_winder_command(const WinderOptions& o) {
    const WinderScene scene = read_winder_file(o.case_file);
    const std::filesystem::path out_dir = results_path(o.output, scene.name, "-winder");
    claim_output(out_dir, o.force);  // refused before any work, never over the user's files
    // Progress: one line rewritten in place on a terminal; in a log (not a
    // terminal) a line at the first diameter, every tenth of the sweep and
    // the last, so that a logged run is never silent for a minute.
    const bool terminal = ::isatty(STDERR_FILENO);
    const auto progress = [&](int i, int n) {
        if (o.quiet) return;
        if (terminal) {
            std::cerr << "\rwinder: diameter " << i << " of " << n << std::flush;
        } else if (const int every = std::max(1, (n + 9) / 10); i == 1 || i == n || i % every == 0) {
            std::cerr << "winder: diameter " << i << " of " << n << std::endl;
        }
    };
    const WinderSweepResult result = run_winder_sweep(scene, progress);
    if (terminal && !o.quiet) std::cerr << "\n";

    ResultsFolder folder(out_dir, o.force);
    const std::filesystem::path& dir = folder.dir();
    write_winder_tables(dir, scene, result);
    // The pictures python/coremodal/winder_plot.py draws.
    const Pictures pictures = draw_pictures("winder-plot", dir, o.no_plots, {"crossing_diagram.png", "response.png"});
    write_text_file(dir / "report.md", winder_report_markdown(scene, result, pictures.pngs, pictures.problem));
    folder.commit();
    std::cout << winder_console_summary(scene, result) << "  results: " << out_dir.string() << "/report.md" << std::endl;
    return 0;
}

}  // namespace

Command add_winder_command(CLI::App& app) {
    auto o = std::make_shared<WinderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "winder", "A two-drum winder ([winder] case file): natural frequencies as the rolls grow, the crossings of "
                  "the rolls' rotation harmonics with the drum modes, X/F at a drum's centre; tables, a crossing "
                  "diagram and report.md");
    cmd->add_option("case", o->case_file, "winder case file (TOML), e.g. cases/11-two-drum-winder.toml")->required();
    add_results_options(cmd, o->output, o->force, "-winder");
    cmd->add_flag("-q,--quiet", o->quiet, "no progress line");
    cmd->add_flag("--no-plots", o->no_plots, "do not run python3 for the PNG plots");
    add_unused_option(cmd, "--mesh", true, "the drums, rolls and rider are beam elements ([winder] elements)");
    cmd->footer("Exit status 0 on success, 1 when the input is wrong (nothing is written then). "
                "The [winder] table: docs/how-to/winder.md.");
    return {cmd, [o] { return run_winder_command(*o); }, false};
}

}  // namespace coremodal
