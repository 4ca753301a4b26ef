// coremodal: natural modes of paper-roll cores, rest rolls and their chucks.
// One subcommand per verb (app/<verb>_command.cpp; `coremodal --help` lists
// them). PETSc and SLEPc options (single dash, e.g.
// -st_pc_factor_mat_solver_type mumps, -eps_view) may follow anywhere; they
// are applied after coremodal's defaults, so an expert can override any
// solver setting.
#include "common/argv.hpp"
#include "app/commands.hpp"
#include "app/folder_case.hpp"
#include "common/error.hpp"
#include "common/join.hpp"
#include "common/mpi_start.hpp"
#include "common/petsc_handle.hpp"
#include "common/signals.hpp"
#include "scene/case_schema.hpp"  // nearest: "did you mean"

#include <gmsh.h>  // GMSH_API_VERSION
#include <slepcsys.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

#define COREMODAL_STRINGIFY(x) #x
#define COREMODAL_VERSION_OF(major, minor, patch) \
    COREMODAL_STRINGIFY(major) "." COREMODAL_STRINGIFY(minor) "." COREMODAL_STRINGIFY(patch)

// The versions this binary was built against (the headers'; Debian's
// packages keep the libraries at the same version).
constexpr const char* kVersionText =
    "coremodal " COREMODAL_VERSION " (built with PETSc " COREMODAL_VERSION_OF(
        PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR, PETSC_VERSION_SUBMINOR) ", SLEPc " COREMODAL_VERSION_OF(SLEPC_VERSION_MAJOR, SLEPC_VERSION_MINOR, SLEPC_VERSION_SUBMINOR) ", gmsh " GMSH_API_VERSION ")";

// "; did you mean 'x'?" when one of `candidates` is near `word`, else "".
std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
    return coremodal::did_you_mean(word, std::vector<std::string_view>(candidates.begin(), candidates.end()));
}

// What CLI11 says tersely about a mistyped command line, said with the
// word that was typed and the nearest valid one: a command that does not
// exist (CLI11: "A subcommand is required") and an option the command does
// not have (CLI11: "The following argument was not expected"). Empty when
// the mistake is another kind; CLI11's own message then stands.
std::optional<std::string> explain_parse_error(const std::vector<coremodal::Command>& commands,
                                               const std::vector<std::string>& args) {
    std::vector<std::string> names;
    for (const coremodal::Command& c : commands) names.push_back(c.cli->get_name());
    const auto word = std::find_if(args.begin() + 1, args.end(), [](const std::string& a) { return a[0] != '-'; });
    if (word == args.end())
        return args.size() == 1 ? std::optional("no command given; expected one of " + coremodal::join(names)) : std::nullopt;
    const auto command = std::find(names.begin(), names.end(), *word);
    if (command == names.end()) {
        const bool case_file = word->ends_with(".toml");
        return "unknown command '" + *word + "'" +
               (case_file ? "; did you mean 'coremodal run " + *word + "' or 'coremodal check " + *word + "'?"
                          : suggestion(*word, names)) +
               "; expected one of " + coremodal::join(names);
    }
    std::vector<std::string> options;
    for (const CLI::Option* o : commands[command - names.begin()].cli->get_options()) {
        for (const std::string& n : o->get_lnames()) options.push_back("--" + n);
        for (const std::string& n : o->get_snames()) options.push_back("-" + n);
    }
    for (auto a = word + 1; a != args.end(); ++a) {
        const std::string name = a->substr(0, a->find('='));
        // Not an option: a value, a negative number, or one the command has.
        if (name.size() < 2 || name[0] != '-' || std::isdigit(static_cast<unsigned char>(name[1])) ||
            std::find(options.begin(), options.end(), name) != options.end())
            continue;
        return "coremodal " + *word + ": unknown option '" + name + "'" + suggestion(name, options) +
               "; expected one of " + coremodal::join(options) + " ('coremodal " + *word + " --help' says what they do)";
    }
    return std::nullopt;
}

int report_error(const char* kind, const std::exception& e) {
    coremodal::wait_if_interrupted();  // an error the interrupt's clean-up caused is no news
    int mpi_up = 0;
    MPI_Initialized(&mpi_up);
    if (!mpi_up || coremodal::mpi_rank() == 0) std::cerr << "coremodal: " << kind << e.what() << std::endl;
    return 1;
}

// The number of processes an MPI launcher (mpirun, srun with PMI) started
// with this one, and this one's rank; 1 and 0 without a launcher. Read from
// the launcher's environment: the commands that do not start MPI need it.
int launched_processes() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
    return 1;
}
int launched_rank() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK"})
        if (const char* value = std::getenv(name)) return std::atoi(value);
    return 0;
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
    // SIGINT and SIGTERM stop children and remove partial folders
    // (common/signals.hpp).
    coremodal::install_interrupt_handling();
    coremodal::SplitArguments args = coremodal::split_petsc_arguments(argc, argv);

    CLI::App app{"coremodal " COREMODAL_VERSION
                 ": natural modes of paper-roll cores, rest rolls and chucks (gmsh, PETSc, SLEPc)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", kVersionText);
    const std::vector<coremodal::Command> commands = {
        coremodal::add_run_command(app),      coremodal::add_check_command(app),
        coremodal::add_beam_command(app),     coremodal::add_batch_command(app),
        coremodal::add_converge_command(app), coremodal::add_winder_command(app),
        coremodal::add_study_command(app),    coremodal::add_calibrate_command(app),
        coremodal::add_schema_command(app),
        coremodal::add_sensitivity_command(app), coremodal::add_fit_command(app),
        coremodal::add_campbell_command(app),
        coremodal::add_response_command(app), coremodal::add_traction_command(app),
        coremodal::add_durability_command(app), coremodal::add_select_command(app),
        coremodal::add_limits_command(app)};

    auto ours = coremodal::c_strings(args.ours);
    try {
        app.parse(static_cast<int>(args.ours.size()), ours.data());
    } catch (const CLI::ParseError& e) {
        // --help and --version end here with 0; a usage error with EX_USAGE.
        const std::optional<std::string> explained = e.get_exit_code() ? explain_parse_error(commands, args.ours) : std::nullopt;
        if (!explained) return app.exit(e) == 0 ? 0 : coremodal::kExitUsage;
        std::cerr << "coremodal: error: " << *explained << std::endl;
        return coremodal::kExitUsage;
    }
    const coremodal::Command* chosen = nullptr;
    for (const auto& c : commands)
        if (c.cli->parsed()) chosen = &c;
    if (!chosen) return 2;
    if (!chosen->needs_petsc) {
        // Without PETSc a command has no work to share among MPI ranks: under
        // mpirun each rank would run it whole and write the same folder.
        if (launched_processes() > 1) {
            if (launched_rank() == 0)
                std::cerr << "coremodal: error: `coremodal " << chosen->cli->get_name() << "` runs in one process ("
                          << launched_processes() << " MPI ranks would each run it and write the same output); run "
                          << "it without mpirun" << std::endl;
            return 1;
        }
        const int status = run_guarded(*chosen);
        coremodal::wait_if_interrupted();
        return status;
    }

    auto petsc = coremodal::c_strings(args.petsc);
    int petsc_argc = static_cast<int>(args.petsc.size());
    char** petsc_argv = petsc.data();
    coremodal::IsolatedMpiSingleton isolated;  // common/mpi_start.hpp: why
    if (SlepcInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr)) return 2;
    isolated.started();
    // PETSc errors become exceptions with coremodal's message; no tracebacks.
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    coremodal::install_interrupt_handling();  // again: PETSc has put its own SIGTERM handler in place
    const int status = run_guarded(*chosen);
    coremodal::wait_if_interrupted();
    PetscPopErrorHandler();  // PETSc's -malloc_dump lists the handler's 32 bytes otherwise
    SlepcFinalize();
    return status;
}
