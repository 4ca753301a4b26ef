// `coremodal converge`: what accuracy costs in time. Runs a refinement ladder
// for every model level the scene allows (model_ladder.hpp), times each level
// (median of repeated runs, ladder_runs.hpp), tracks the modes across levels
// by label and extrapolates their frequencies (model_study.hpp), and writes
// converge.csv, converge.json, converge.md and error_vs_time.png
// (output/converge_report.hpp). docs/validation/accuracy-vs-cost.md.
#pragma once

#include "analyses/converge/converge_study.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace coremodal {

// The finest level's default DOF bound: ~190 k DOFs solve in about 85 s on
// the 2-core reference machine (bench/results/log.md), so that a four-level
// study of the 4.32 m rest roll fits in a few minutes.
inline constexpr long kDefaultMaxDofs = 200000;

struct ConvergeOptions {
    std::string case_file;
    std::optional<std::string> output_dir;  // default results/<case name>-converge
    bool force = false;                     // an earlier result there is removed, not kept as .previous
    int levels = 4;                         // k = first ... first + levels - 1
    int first = 1;
    std::optional<std::string> unit;        // "W/P/A/Z"; default: default_unit(scene)
    int repeats = 3;                        // runs per level; the median time is reported
    double repeat_limit_s = 30;             // a level whose first run takes longer runs once
    long max_dofs = kDefaultMaxDofs;        // bound on the finest level (fit_unit_to_budget); 0: none
    std::optional<int> n_modes;             // modes per run; default: the case's, raised
                                            // until the coarsest level shows an ovalling mode
    std::vector<std::string> check_levels;  // named mesh levels to compare with f0
    // Model levels to run: those of them the scene allows (the beam and the
    // harmonic level are skipped, with a note, for a scene they cannot solve).
    std::vector<std::string> models = {"solid", "beam", "harmonic"};
    bool quiet = false;
    bool write_results = true;
    bool plots = true;  // error_vs_time.png (python); false: --no-plots
    // Where the study goes, given by the caller (output/converge_report.hpp:
    // attach_converge_writers, what `coremodal converge` passes), so that the
    // study itself writes nothing: `claim` checks and takes the results
    // folder before any work (with write_results), `write` writes it and
    // prints the summary (rank 0). Empty: nothing claimed, written or printed.
    std::function<void(const std::filesystem::path& out, const ConvergeOptions& options)> claim;
    std::function<void(const ConvergeStudy& study, const std::filesystem::path& out, const ConvergeOptions& options,
                       std::ostream& progress)>
        write;
};

// Runs the study and hands it to options.write; collective. Throws
// InputError for bad options or case files.
ConvergeStudy run_converge(const ConvergeOptions& options, std::ostream& progress);

}  // namespace coremodal
