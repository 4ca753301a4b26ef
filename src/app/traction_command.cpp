// `coremodal traction CASE.toml [--output DIR] [--no-plots] [--force]`:
// will the web hold on its roller at speed? Rice & Gans' model of the air
// film between web and roller over the case's [traction] table: the
// effective clearance, the traction and effective friction against web
// speed, the zero-traction speed, the grooves' gain over a plain roller and
// the paper's validity limits at every point (docs/how-to/traction.md). Closed
// forms only: no mesh, no PETSc.
#include "app/commands.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/stopwatch.hpp"
#include "common/warnings.hpp"
#include "output/python_plots.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"
#include "output/traction_report.hpp"
#include "scene/traction_case.hpp"
#include "traction/traction_sweep.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace coremodal {
namespace {

struct TractionOptions {
    std::string case_file, output;
    bool no_plots = false, force = false, quiet = false;
};

int run_traction_command(const TractionOptions& o) {
    const Stopwatch clock;
    // 1. The case's [traction] (the whole file checked when it is a stand scene).
    const std::optional<TractionCase> tc = read_traction_case(o.case_file);
    if (!tc)
        throw InputError(o.case_file + ": no [traction] table; expected one with the roller and the web "
                                       "(roller_radius, wrap, tension, friction, roughnesses, web; docs/how-to/traction.md)");
    print_warnings(tc->warnings);
    // 2. Where the results go, refused before any work if it is not ours to write.
    const std::filesystem::path out_dir = results_path(o.output, tc->name, "-traction");
    claim_output(out_dir, o.force);
    // 3. The model at every speed, the speeds where traction ends.
    const TractionSweep sweep = run_traction_sweep(tc->spec);
    if (sweep.n_invalid > 0) {  // said on stderr too: the numbers there are outside what the paper vouches for
        const auto first = std::find_if(sweep.points.begin(), sweep.points.end(), [](const TractionPoint& p) {
            return !p.valid;
        });
        print_warnings({std::to_string(sweep.n_invalid) + " of " + std::to_string(sweep.points.size()) +
                        " web speeds are outside Rice & Gans' validity limits, the first at " +
                        significant(first->web_speed, 4) + " m/s: " + first->violations.front() +
                        " (report.md, \"Validity\")"});
    }
    // 4. Tables, picture, report; the folder appears complete or not at all.
    ResultsFolder folder(out_dir, o.force);
    const std::filesystem::path& dir = folder.dir();
    write_traction_tables(dir, *tc, sweep, clock.seconds());
    const Pictures pictures = draw_pictures("traction-plot", dir, o.no_plots, {"traction.png"});
    write_text_file(dir / "report.md", traction_report_markdown(*tc, sweep, pictures.pngs, pictures.problem));
    folder.commit();
    std::cout << traction_console_summary(*tc, sweep) << "  results: " << out_dir.string() << "/report.md"
              << std::endl;
    return 0;
}

}  // namespace

Command add_traction_command(CLI::App& app) {
    auto o = std::make_shared<TractionOptions>();
    CLI::App* cmd = app.add_subcommand(
        "traction", "Web-to-roller traction on one roller ([traction] table, Rice & Gans): traction and effective "
                    "friction against web speed, the zero-traction speed, the grooves' gain, the validity limits; "
                    "traction.csv, summary.json, a plot and report.md");
    cmd->add_option("case", o->case_file, "case file (TOML) with a [traction] table, e.g. cases/19-grooved-idler-traction.toml")
        ->required();
    add_results_options(cmd, o->output, o->force, "-traction");
    cmd->add_flag("--no-plots", o->no_plots, "do not run python3 for the PNG plot");
    cmd->add_flag("-q,--quiet", o->quiet, "no progress lines (as the other commands take it; closed forms print none)");
    cmd->footer("Exit status 0 on success, 1 when the input is wrong (nothing is written then). "
                "The [traction] table: docs/how-to/traction.md.");
    return {cmd, [o] { return run_traction_command(*o); }, false};
}

}  // namespace coremodal
