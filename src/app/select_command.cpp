// `coremodal select SELECTION.toml`: which core grade carries which reel in
// which stand — each core's largest roll weight from its durability, its
// largest reel width from the rest roll's verdict (`limits` at the beam
// level, calibrated to the stand's k), the chart of the two
// (the form of Figs. 18–19 of M. Ilomäki, "On the durability of cores and
// rest roll dynamics") and the verdict on each reel asked
// (docs/how-to/durability.md, "Choosing a core"). Beam level only (Eigen): no mesh.
#include "app/commands.hpp"
#include "common/stopwatch.hpp"
#include "output/python_plots.hpp"
#include "output/results_folder.hpp"
#include "output/selection_report.hpp"
#include "output/text_file.hpp"
#include "analyses/select/core_selection.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace coremodal {
namespace {

struct SelectOptions {
    std::string case_file, output;
    bool quiet = false, no_plots = false, force = false;
};

int run_select_command(const SelectOptions& o) {
    const Stopwatch clock;
    const SelectionScene scene = read_selection_file(o.case_file);
    const std::filesystem::path out_dir = results_path(o.output, scene.name, "-select");
    claim_output(out_dir, o.force);  // refused before any work, never over the user's files
    const SelectionResult result = select_cores(scene);
    if (!o.quiet) {
        for (const std::string& d : scene.defaults) std::cout << "select: default " << d << std::endl;
        for (const std::string& l : selection_console_lines(scene, result)) std::cout << "select: " << l << std::endl;
    }
    ResultsFolder folder(out_dir, o.force);
    write_selection_tables(folder.dir(), scene, result, clock.seconds());
    // The chart python/coremodal/selection_plot.py draws (Figs. 18-19).
    const Pictures pictures = draw_pictures("selection-plot", folder.dir(), o.no_plots, {"selection_chart.png"});
    write_text_file(folder.dir() / "report.md", selection_report_markdown(scene, result, pictures.pngs, pictures.problem));
    folder.commit();
    std::cout << "select: results: " << out_dir.string() << "/report.md" << std::endl;
    return 0;
}

}  // namespace

Command add_select_command(CLI::App& app) {
    auto o = std::make_shared<SelectOptions>();
    CLI::App* cmd = app.add_subcommand(
        "select", "Core selection ([selection] file): each core grade's largest roll weight (durability, scaled to "
                  "the stand's chuck and winder) and largest reel width (the limits verdict of the rest roll at the beam level, calibrated to k) per stand; "
                  "the chart, the cores that pass each reel, the lightest and cheapest");
    cmd->add_option("case", o->case_file, "core-selection file (TOML), e.g. cases/18-core-selection.toml")->required();
    add_results_options(cmd, o->output, o->force, "-select");
    cmd->add_flag("-q,--quiet", o->quiet, "no lines per stand and reel");
    cmd->add_flag("--no-plots", o->no_plots, "do not run python3 for the chart");
    cmd->footer("Exit status 0 on success, 1 when the input is wrong (nothing is written then). docs/how-to/durability.md.");
    return {cmd, [o] { return run_select_command(*o); }, false};
}

}  // namespace coremodal
