#include "output/run_writer.hpp"

#include "common/petsc_handle.hpp"
#include "output/run_folder.hpp"
#include "output/side_by_side.hpp"
#include "output/summary.hpp"

#include <filesystem>
#include <iostream>
#include <string>

namespace coremodal {

void write_run(const RunReport& report, const ModelLevel& level, const RunOptions& options) {
    if (mpi_rank() != 0) return;
    if (!options.quiet) {
        print_mode_table(std::cout, report);
        print_verification_and_beam(std::cout, report);
        if (!report.rigid_comparison.empty()) print_side_by_side(std::cout, report.rigid_comparison);
        std::cout << level.console_note();
    }
    if (!options.write_results) return;
    const std::filesystem::path dir = options.output_dir ? std::filesystem::path(*options.output_dir)
                                                         : std::filesystem::path("results") / report.scene.name;
    const std::string last = std::to_string(level.steps());
    Printer{!options.quiet}("[" + last + "/" + last + "] writing " + dir.string());
    write_run_folder(report, dir, options.force, [&](ResultsFolder& folder) {
        return write_level_shapes(folder, report, level.shapes(), options.plots);
    });
}

}  // namespace coremodal
