// A case with [response], run by `coremodal response` or `coremodal run`
// (app/response_command.cpp): checks the results folder before any work,
// then writes response.csv, peaks.csv, summary.json, report.md and
// response.png. Returns the exit code; throws InputError on a wrong case.
#pragma once

#include "app/commands.hpp"

#include <string>

namespace coremodal {

int run_response_case(const std::string& case_file, const std::string& model, const std::string& output, bool force,
                      bool no_plots, bool quiet);

// `coremodal response` (declared here, not in commands.hpp, which every
// command includes).
Command add_response_command(CLI::App& app);

}  // namespace coremodal
