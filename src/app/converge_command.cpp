// `coremodal converge CASE.toml`: the command line of the accuracy-vs-cost
// study (analyses/converge/converge.hpp runs it; docs/validation/accuracy-vs-cost.md).
#include "analyses/converge/converge.hpp"
#include "app/commands.hpp"
#include "output/converge_report.hpp"

#include <iostream>
#include <memory>
#include <string>

namespace coremodal {
namespace {

// The command line before it becomes ConvergeOptions: an empty string or a
// zero count stands for "not given".
struct ConvergeLine {
    ConvergeOptions options;
    std::string output, unit;
    int n_modes = 0;
    bool no_plots = false;
};

// The case, the results folder and the solid's ladder.
void add_ladder_options(CLI::App* cmd, ConvergeLine& line) {
    ConvergeOptions& o = line.options;
    cmd->add_option("case", o.case_file, "case file (TOML) with a generated mesh")->required();
    add_results_options(cmd, line.output, o.force, "-converge");  // converge.md, .csv, .json, error_vs_time.png
    cmd->add_option("--levels", o.levels, "levels of the ladder, k = first ... first + levels - 1 (at least 3)")
        ->capture_default_str()
        ->check(CLI::Range(3, 12));
    cmd->add_option("--first", o.first, "multiple k of the coarsest level")->capture_default_str()->check(
        CLI::Range(1, 64));
    cmd->add_option("--unit", line.unit,
                    "element counts of the k = 1 mesh, WALL/PAPER/AROUND/ALONG (default: 1/1/8 and along keeping the "
                    "case's element aspect)");
}

// Repeats, cost bound, modes, named levels, model levels.
void add_run_options(CLI::App* cmd, ConvergeLine& line) {
    ConvergeOptions& o = line.options;
    cmd->add_option("--repeats", o.repeats, "runs per level; the median time is reported")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    cmd->add_option("--repeat-limit", o.repeat_limit_s, "seconds: a level whose first run is slower runs once")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-dofs", o.max_dofs,
                    "bound on the finest level's DOFs: the default unit's elements along are lowered to stay "
                    "within it (0: no bound; an explicit --unit is taken as given)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--modes", line.n_modes,
                    "modes per run (default: the case's, doubled until the coarsest level shows an ovalling mode)")
        ->check(CLI::Range(1, 10000));
    cmd->add_option("--check-levels", o.check_levels,
                    "named mesh levels (coarse, default, fine, very_fine) to run once and compare with the "
                    "extrapolated frequencies")
        ->delimiter(',');
    cmd->add_option("--models", o.models,
                    "model levels to run, comma-separated: solid, harmonic, beam (default all three; the harmonic "
                    "level is skipped for a scene that is not axisymmetric, the beam for one it cannot solve, with "
                    "the reason in converge.md)")
        ->delimiter(',');
    cmd->add_flag("-q,--quiet", o.quiet, "no progress lines or summary");
    cmd->add_flag("--no-plots", line.no_plots, "do not run python3 for error_vs_time.png");
    add_unused_option(cmd, "--mesh", true,
                      "it runs its own ladder of meshes (--first, --levels); named levels to compare go in "
                      "--check-levels");
}

// The ladders in one paragraph; docs/validation/accuracy-vs-cost.md says the rest.
constexpr const char* kConvergeFooter =
    "Model levels: solid, harmonic and beam. Solid level k refines the unit mesh k times in every direction "
    "(--levels, --first, --unit, --max-dofs, --repeats apply to it); the harmonic ladder (r-z section only; exact in "
    "theta) meshes the same section two levels finer; the beam ladder is 4 to 64 Timoshenko elements. The three "
    "finest levels of each give the Richardson extrapolation. PETSc/SLEPc options pass through as for `run`. See "
    "docs/validation/accuracy-vs-cost.md.";

}  // namespace

Command add_converge_command(CLI::App& app) {
    auto line = std::make_shared<ConvergeLine>();
    CLI::App* cmd = app.add_subcommand(
        "converge",
        "What accuracy costs in time: a mesh refinement ladder per model level, timed (median of repeated runs), "
        "modes tracked by label, Richardson-extrapolated frequencies with error estimates, error-vs-time plot");
    add_ladder_options(cmd, *line);
    add_run_options(cmd, *line);
    cmd->footer(kConvergeFooter);
    auto run = [line] {
        ConvergeOptions& o = line->options;
        if (!line->output.empty()) o.output_dir = line->output;
        if (!line->unit.empty()) o.unit = line->unit;
        if (line->n_modes > 0) o.n_modes = line->n_modes;
        o.plots = !line->no_plots;
        attach_converge_writers(o);
        run_converge(o, std::cout);
        return 0;
    };
    return {cmd, run, true};
}

}  // namespace coremodal
