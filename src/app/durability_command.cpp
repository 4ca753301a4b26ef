// `coremodal durability DATA.csv [--confidence C] [--probability P ...]`: a
// core's winding–unwinding simulator results fitted and reduced to the roll
// weight each failure probability allows, by M. Ilomäki's statistics
// ({16}–{32}; docs/how-to/durability.md). Plain numbers: no mesh, no PETSc.
#include "app/commands.hpp"
#include "common/error.hpp"
#include "common/stopwatch.hpp"
#include "common/format.hpp"
#include "durability/durability_analysis.hpp"
#include "output/durability_report.hpp"
#include "output/python_plots.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace coremodal {
namespace {

struct DurabilityOptions {
    std::string data, output;
    double confidence = kDefaultConfidence;
    std::vector<double> probabilities;
    bool quiet = false, no_plots = false, force = false;
};

// The command line's numbers, checked before any work.
void check_levels(const DurabilityOptions& o) {
    if (!(o.confidence >= 0.5 && o.confidence < 1))
        throw InputError("--confidence " + significant(o.confidence) +
                         " is outside [0.5, 1); expected a confidence level such as 0.95 or 0.99 ({23}, {26})");
    for (double p : o.probabilities)
        if (!(p > 0 && p <= 0.5))
            throw InputError("--probability " + significant(p) +
                             " is outside (0, 0.5]; expected a failure probability such as 1e-5 ({27}: 0.5 is the "
                             "mean curve itself)");
}

int run_durability_command(DurabilityOptions o) {
    const Stopwatch clock;
    if (o.probabilities.empty()) o.probabilities.assign(std::begin(kTable3Probabilities), std::end(kTable3Probabilities));
    check_levels(o);
    const DurabilityData data = read_durability_data(o.data);
    const std::filesystem::path out_dir =
        results_path(o.output, std::filesystem::path(o.data).stem().string(), "-durability");
    claim_output(out_dir, o.force);  // refused before any work, never over the user's files
    const DurabilityAnalysis analysis = analyse_durability(data, o.confidence, o.probabilities);
    const std::vector<std::string> steps = durability_steps(data, analysis);
    if (!o.quiet)
        for (const std::string& s : steps) std::cout << "durability: " << s << std::endl;

    ResultsFolder folder(out_dir, o.force);
    write_durability_tables(folder.dir(), data, analysis, clock.seconds());
    // The picture python/coremodal/durability_plot.py draws (Figs. 16-17).
    const Pictures pictures = draw_pictures("durability-plot", folder.dir(), o.no_plots, {"durability.png"});
    write_text_file(folder.dir() / "report.md", durability_report_markdown(data, analysis, pictures.pngs, pictures.problem));
    folder.commit();
    std::cout << "durability: 9. results: " << out_dir.string() << "/report.md" << std::endl;
    return 0;
}

}  // namespace

Command add_durability_command(CLI::App& app) {
    auto o = std::make_shared<DurabilityOptions>();
    CLI::App* cmd = app.add_subcommand(
        "durability", "A core's winding-unwinding simulator results (CSV) fitted by Ilomaki's power law and reduced "
                      "to the roll weight each failure probability allows ({16}-{32}); tables, a plot and report.md");
    cmd->add_option("data", o->data, "simulator results (CSV with units in the header and the test chuck), e.g. "
                                     "cases/18-core-durability-76x15.csv")
        ->required();
    add_results_options(cmd, o->output, o->force, "-durability");
    cmd->add_option("-c,--confidence", o->confidence,
                    "confidence level C of the mean and the standard deviation ({22}-{26}); default 0.99, the "
                    "paper's example");
    cmd->add_option("-p,--probability", o->probabilities,
                    "failure probabilities P in (0, 0.5] of the reduced curves ({27}), repeatable; default Table 3's: "
                    "0.5 0.01 0.001 1e-4 1e-5 1e-6");
    cmd->add_flag("-q,--quiet", o->quiet, "no step lines");
    cmd->add_flag("--no-plots", o->no_plots, "do not run python3 for the PNG plot");
    cmd->footer("Exit status 0 on success, 1 when the data or an option is wrong (nothing is written then). "
                "docs/how-to/durability.md.");
    return {cmd, [o] { return run_durability_command(*o); }, false};
}

}  // namespace coremodal
