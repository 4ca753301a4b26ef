// Each subcommand of the coremodal program registers itself with the
// command line and returns what to run once the line is parsed. main() then
// starts PETSc/SLEPc only for commands that need it.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>

namespace coremodal {

struct Command {
    CLI::App* cli = nullptr;
    std::function<int()> run;  // returns the process exit code
    bool needs_petsc = true;
};

Command add_run_command(CLI::App& app);    // app/run_command.cpp
Command add_beam_command(CLI::App& app);   // app/beam_command.cpp
Command add_batch_command(CLI::App& app);  // app/batch_command.cpp
Command add_converge_command(CLI::App& app);  // app/converge_command.cpp
Command add_study_command(CLI::App& app);  // app/study_command.cpp
Command add_calibrate_command(CLI::App& app);  // app/calibrate_command.cpp
Command add_check_command(CLI::App& app);  // app/check_command.cpp
Command add_winder_command(CLI::App& app);  // app/winder_command.cpp
Command add_schema_command(CLI::App& app);  // app/schema_command.cpp

}  // namespace coremodal
