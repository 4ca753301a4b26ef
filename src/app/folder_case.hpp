// The commands whose case writes one results folder with one picture:
// `campbell` (a [rotation] table) and `response` (a [response] table), also
// reached through `coremodal run` on such a case. Their command line, the
// checks before any work and the writing of the folder are said once here;
// each command file says only its analysis (app/campbell_command.cpp,
// app/response_command.cpp).
#pragma once

#include "app/commands.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace coremodal {

struct FolderCaseOptions {
    std::string case_file, output, model;  // "" output: results/<case name><suffix>
    std::string mesh;                      // --mesh LEVEL, "" for the case's own [mesh]
    bool quiet = false, no_plots = false, force = false;
    // campbell: modes that fail their verification written, marked
    // (modes/verification_check.hpp); a response is never made of them.
    bool keep_going = false;
};

// The case, -o/--output, --force, --model, -m/--mesh, -q and --no-plots.
void add_folder_case_options(CLI::App* cmd, FolderCaseOptions& o, const std::string& case_help,
                             const std::string& suffix, const std::string& png);

// Before any work, once the scene is known to be one the analysis runs: the
// results folder chosen and refused if it is not coremodal's
// (output/results_folder.hpp), the scene's warnings printed. Returns the folder.
std::filesystem::path prepare_folder_case(const FolderCaseOptions& o, const Scene& scene, const std::string& suffix);

// --model and --mesh applied to the case's scene (a mesh level is refused,
// naming the levels, for a user mesh file).
void apply_level_options(const FolderCaseOptions& o, Scene& scene);

// What an analysis puts into its folder.
struct FolderContents {
    std::function<void(const std::filesystem::path& dir)> tables;
    std::string plot_command, png;  // `python3 -m coremodal PLOT_COMMAND DIR` draws PNG
    // report.md from the pictures drawn and, when there are none, why.
    std::function<std::string(const std::vector<std::string>& pngs, const std::string& plot_problem)> report;
    std::string console;  // printed unless --quiet
};

// Writes the tables, the picture (a failed plot is a warning: the tables
// and report.md are complete without it) and report.md into a partial
// folder, then puts it in place. Returns the exit code.
int write_folder_case(const FolderCaseOptions& o, const std::filesystem::path& out_dir, const FolderContents& contents);

// Refuses more than one MPI rank before any work: a Campbell sweep and a
// forced response run in one process (`command`: "a Campbell sweep").
void require_one_process(const FolderCaseOptions& o, const std::string& command);

// The two analyses (a case without their table is an InputError).
int run_rotating_case(const FolderCaseOptions& o);  // app/campbell_command.cpp
int run_response_case(const FolderCaseOptions& o);  // app/response_command.cpp
Command add_campbell_command(CLI::App& app);
Command add_response_command(CLI::App& app);

}  // namespace coremodal
