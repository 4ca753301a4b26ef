#include "app/folder_case.hpp"

#include "common/error.hpp"
#include "common/petsc_handle.hpp"
#include "output/python_plots.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"
#include "scene/mesh_levels.hpp"

#include <iostream>

namespace coremodal {

void add_folder_case_options(CLI::App* cmd, FolderCaseOptions& o, const std::string& case_help,
                             const std::string& suffix, const std::string& png) {
    cmd->add_option("case", o.case_file, case_help)->required();
    add_results_options(cmd, o.output, o.force, suffix);
    add_model_option(cmd, o.model);
    add_mesh_option(cmd, o.mesh);
    cmd->add_flag("-q,--quiet", o.quiet, "print only where the results are");
    cmd->add_flag("--no-plots", o.no_plots, "do not run python3 for " + png);
}

void require_one_process(const FolderCaseOptions& o, const std::string& command) {
    if (mpi_size() > 1)
        throw InputError(o.case_file + ": " + command + " runs in one process (" + std::to_string(mpi_size()) +
                         " MPI ranks would each run it and write the same results folder); run it without mpirun");
}

void apply_level_options(const FolderCaseOptions& o, Scene& scene) {
    if (!o.model.empty()) scene.model = model_option(o.model);
    if (!o.mesh.empty()) apply_mesh_level(scene, o.mesh);
}

std::filesystem::path prepare_folder_case(const FolderCaseOptions& o, const Scene& scene, const std::string& suffix) {
    const std::filesystem::path out_dir = results_path(o.output, scene.name, suffix);
    claim_output(out_dir, o.force);  // refused before any work, never over the user's files
    for (const std::string& w : scene.warnings) std::cerr << "coremodal: warning: " << w << std::endl;
    return out_dir;
}

int write_folder_case(const FolderCaseOptions& o, const std::filesystem::path& out_dir, const FolderContents& contents) {
    ResultsFolder folder(out_dir, o.force);
    const std::filesystem::path& dir = folder.dir();
    contents.tables(dir);
    const Pictures pictures = draw_pictures(contents.plot_command, dir, o.no_plots, {contents.png});
    write_text_file(dir / "report.md", contents.report(pictures.pngs, pictures.problem));
    folder.commit();
    if (!o.quiet) std::cout << contents.console;
    std::cout << "  results: " << out_dir.string() << "/report.md" << std::endl;
    return 0;
}

}  // namespace coremodal
