// coremodal: natural modes of paper-roll cores, rest rolls and their chucks.
//
//   coremodal run CASE.toml [--output DIR] [--mesh LEVEL] [PETSc/SLEPc options]
//   coremodal beam ...      (beam formulas, no mesh)
//   coremodal batch ...     (many cases, in parallel processes)
//   coremodal converge CASE.toml [--output DIR]   (accuracy against cost: refinement ladder)
//   coremodal study CASE.toml [--output DIR]      (a [study] table: a sweep, modes tracked by MAC)
//   coremodal calibrate CASE.toml [--output DIR]  (a [calibration] table: k fitted for `beam --calibration`)
//
// PETSc and SLEPc options (single dash, e.g. -st_pc_factor_mat_solver_type
// mumps, -eps_view) may follow anywhere; they are applied after coremodal's
// defaults, so an expert can override any solver setting.
#include "common/argv.hpp"
#include "app/commands.hpp"
#include "common/error.hpp"
#include "common/petsc_handle.hpp"

#include <slepcsys.h>

#include <iostream>
#include <string>
#include <vector>

namespace {

// A PETSc option is a single dash followed by a word with an underscore
// ("-eps_view", "-log_view", "-st_pc_factor_mat_solver_type"); its value, if
// any, is the next argument unless that looks like an option or a case file.
bool is_petsc_option(const std::string& a) {
    return a.size() > 2 && a[0] == '-' && a[1] != '-' && a.find('_') != std::string::npos;
}
bool is_option_value(const std::string& a) {
    return !a.empty() && a[0] != '-' && a.find(".toml") == std::string::npos;
}

struct SplitArgs {
    std::vector<std::string> ours;   // argv[0] and coremodal's own arguments
    std::vector<std::string> petsc;  // argv[0] and PETSc's
};

SplitArgs split_arguments(int argc, char** argv) {
    SplitArgs s;
    s.ours.push_back(argv[0]);
    s.petsc.push_back(argv[0]);
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (is_petsc_option(a)) {
            s.petsc.push_back(a);
            if (i + 1 < argc && is_option_value(argv[i + 1])) s.petsc.push_back(argv[++i]);
        } else {
            s.ours.push_back(a);
        }
    }
    return s;
}

int report_error(const char* kind, const std::exception& e) {
    int mpi_up = 0;
    MPI_Initialized(&mpi_up);
    if (!mpi_up || coremodal::mpi_rank() == 0) std::cerr << "coremodal: " << kind << e.what() << std::endl;
    return 1;
}

int run_guarded(const coremodal::Command& command) {
    try {
        return command.run();
    } catch (const coremodal::InputError& e) {
        return report_error("error: ", e);
    } catch (const coremodal::SolveError& e) {
        return report_error("solve failed: ", e);
    } catch (const std::exception& e) {
        return report_error("", e);
    }
}

}  // namespace

int main(int argc, char** argv) {
    SplitArgs args = split_arguments(argc, argv);

    CLI::App app{"coremodal " COREMODAL_VERSION
                 ": natural modes of paper-roll cores, rest rolls and chucks (gmsh, PETSc, SLEPc)"};
    app.require_subcommand(1);
    const std::vector<coremodal::Command> commands = {
        coremodal::add_run_command(app),      coremodal::add_beam_command(app),
        coremodal::add_batch_command(app),    coremodal::add_converge_command(app),
        coremodal::add_winder_command(app),
        coremodal::add_study_command(app),    coremodal::add_calibrate_command(app)};

    auto ours = coremodal::c_strings(args.ours);
    try {
        app.parse(static_cast<int>(args.ours.size()), ours.data());
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    const coremodal::Command* chosen = nullptr;
    for (const auto& c : commands)
        if (c.cli->parsed()) chosen = &c;
    if (!chosen) return 2;
    if (!chosen->needs_petsc) return run_guarded(*chosen);

    auto petsc = coremodal::c_strings(args.petsc);
    int petsc_argc = static_cast<int>(args.petsc.size());
    char** petsc_argv = petsc.data();
    if (SlepcInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr)) return 2;
    // PETSc errors become exceptions with coremodal's message; no tracebacks.
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    const int status = run_guarded(*chosen);
    SlepcFinalize();
    return status;
}
