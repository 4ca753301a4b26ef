// A case with [rotation], run by `coremodal campbell` or `coremodal run`
// (app/campbell_command.cpp): checks the results folder before any work,
// then writes campbell.csv, critical_speeds.csv, summary.json, report.md and
// campbell.png. Returns the exit code; throws InputError on a wrong case.
#pragma once

#include "app/commands.hpp"

#include <string>

namespace coremodal {

int run_rotating_case(const std::string& case_file, const std::string& model, const std::string& output, bool force,
                      bool no_plots, bool quiet);

// `coremodal campbell` (declared here, not in commands.hpp, which every
// command includes).
Command add_campbell_command(CLI::App& app);

}  // namespace coremodal
