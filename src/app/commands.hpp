// Each subcommand of the coremodal program registers itself with the
// command line and returns what to run once the line is parsed. main() then
// starts PETSc/SLEPc only for commands that need it.
#pragma once

#include "scene/model_choice.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace coremodal {

struct Command {
    CLI::App* cli = nullptr;
    std::function<int()> run;  // returns the process exit code
    bool needs_petsc = true;
};

// Options several commands share, said once.
// The words --model takes: scene/model_choice's, the case file's.
inline std::vector<std::string> model_words() {
    const std::vector<std::string_view>& words = model_choice_words();
    return {words.begin(), words.end()};
}
// --model: the model level, overriding the case's model key (`what`: "" for
// a run, " of every point" for a sweep).
inline CLI::Option* add_model_option(CLI::App* cmd, std::string& model, const std::string& what = "") {
    return cmd->add_option("--model", model,
                           "model level" + what + ", overriding the case's model key: solid (3D), harmonic "
                           "(axisymmetric scenes, one 2D problem per wave number n), coupled (harmonics coupled by "
                           "segmented chucks, a chuck not expanded or the web, one 2D-cost problem), auto (harmonic "
                           "where the scene allows it, else coupled where it allows that, else solid), beam")
        ->check(CLI::IsMember(model_words()));
}
// -m/--mesh: the mesh level of a generated mesh, overriding the case's [mesh].
inline CLI::Option* add_mesh_option(CLI::App* cmd, std::string& mesh) {
    return cmd->add_option("-m,--mesh", mesh,
                           "mesh level for a generated mesh, overriding the case: coarse, default, fine, very_fine");
}
// An option every command accepts (--mesh, --no-plots) that this one has no
// use for: accepted, and answered with a note on stderr saying why, so that
// one command line works for every command.
inline void add_unused_option(CLI::App* cmd, const std::string& name, bool takes_value, const std::string& why) {
    const std::string note = "coremodal: note: " + name + " is not used by `coremodal " + cmd->get_name() + "`: " + why;
    const auto say = [note](const auto&) { std::cerr << note << std::endl; };
    if (takes_value)
        cmd->add_option_function<std::string>(name, say, "not used by this command: " + why)->type_name("VALUE");
    else
        cmd->add_flag_function(name, [say](std::int64_t count) { say(count); }, "not used by this command: " + why);
}

// The exit status of a command line that cannot be parsed (an unknown
// command or option, a missing or invalid value): EX_USAGE of BSD's
// sysexits.h, 64 (docs/reference/results.md).
inline constexpr int kExitUsage = 64;

// -o/--output and --force of a command that writes one results folder
// (default results/<case name><suffix>).
inline void add_results_options(CLI::App* cmd, std::string& output, bool& force, const std::string& suffix) {
    cmd->add_option("-o,--output", output,
                    "results folder (default results/<case name>" + suffix + "); replaces only an earlier coremodal "
                    "result, which is kept as <folder>.previous (docs/reference/results.md)");
    cmd->add_flag("--force", force, "remove the earlier result at --output instead of keeping it as .previous");
}

// The command line of a sweep over a case's [study] or [calibration] table.
struct SweepCommandOptions {
    std::string case_file, output, mesh, model;
    bool quiet = false, no_plots = false, force = false;
    unsigned jobs = 0;  // 0: the number of cores
};
// Its case, results folder, --model, --mesh, -q, --no-plots and --jobs.
inline void add_sweep_options(CLI::App* cmd, SweepCommandOptions& o, const std::string& table,
                              const std::string& example = "") {
    cmd->add_option("case", o.case_file, "case file (TOML) with a [" + table + "] table" + example)->required();
    add_results_options(cmd, o.output, o.force, "-" + table);
    add_model_option(cmd, o.model, " of every point");
    cmd->add_option("-m,--mesh", o.mesh,
                    "mesh level of every point, overriding [" + table + "] mesh: coarse, default, fine, very_fine");
    cmd->add_flag("-q,--quiet", o.quiet, "no progress lines");
    cmd->add_flag("--no-plots", o.no_plots, "do not run python3 for the PNG plots");
    cmd->add_option("-j,--jobs", o.jobs,
                    "points run at the same time, each in its own process (default: the number of cores; 1: one "
                    "after the other in this process, as always under mpirun)");
}

Command add_run_command(CLI::App& app);    // app/run_command.cpp
Command add_beam_command(CLI::App& app);   // app/beam_command.cpp
Command add_batch_command(CLI::App& app);  // app/batch_command.cpp
Command add_converge_command(CLI::App& app);  // app/converge_command.cpp
Command add_study_command(CLI::App& app);  // app/study_command.cpp
Command add_calibrate_command(CLI::App& app);  // app/calibrate_command.cpp
Command add_sensitivity_command(CLI::App& app);  // app/sensitivity_command.cpp
Command add_fit_command(CLI::App& app);          // app/fit_command.cpp
Command add_check_command(CLI::App& app);  // app/check_command.cpp
Command add_winder_command(CLI::App& app);  // app/winder_command.cpp
Command add_schema_command(CLI::App& app);  // app/schema_command.cpp
Command add_traction_command(CLI::App& app);  // app/traction_command.cpp
Command add_durability_command(CLI::App& app);  // app/durability_command.cpp
Command add_select_command(CLI::App& app);      // app/select_command.cpp
Command add_limits_command(CLI::App& app);  // app/limits_command.cpp

}  // namespace coremodal
