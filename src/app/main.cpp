// coremodal: natural modes of paper-roll cores, rest rolls and their chucks.
// One subcommand per verb (app/<verb>_command.cpp; `coremodal --help` lists
// them). PETSc and SLEPc options (single dash, e.g.
// -st_pc_factor_mat_solver_type mumps, -eps_view) may follow anywhere; they
// are applied after coremodal's defaults, so an expert can override any
// solver setting.
#include "common/argv.hpp"
#include "common/blas_threads.hpp"
#include "app/commands.hpp"
#include "app/folder_case.hpp"
#include "common/error.hpp"
#include "common/free_memory.hpp"
#include "common/huge_pages.hpp"
#include "common/join.hpp"
#include "common/mpi_start.hpp"
#include "common/petsc_handle.hpp"
#include "common/signals.hpp"
#include "scene/case_schema.hpp"  // nearest: "did you mean"

#include <gmsh.h>  // GMSH_API_VERSION
#include <slepcsys.h>
#include <cxxabi.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <new>
#include <typeinfo>
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

// PETSc's own words for the last error it raised (its first line, where it
// was detected): COREMODAL_PETSC's exception carries only the code and the
// call. Kept by the error handler main() installs.
struct PetscFailure {
    PetscErrorCode code = 0;
    std::string message;
};
PetscFailure last_petsc_failure;

PetscErrorCode remember_petsc_error(MPI_Comm, int, const char*, const char*, PetscErrorCode n, PetscErrorType p,
                                    const char* message, void*) {
    if (p == PETSC_ERROR_INITIAL) last_petsc_failure = {n, message ? message : ""};
    return n;  // as PetscReturnErrorHandler: the caller gets the code, nothing is printed
}

bool mentions(const std::string& text, const char* part) { return text.find(part) != std::string::npos; }

// A raw solver error ("PETSc error 55 in MatLUFactorNumeric(...)") said as
// what went wrong and what to do; the raw words stay at the end for a report.
std::string explain_petsc_error(const std::string& raw) {
    const int code = std::atoi(raw.c_str() + std::strlen("PETSc error "));
    const char* meaning = nullptr;
    PetscErrorMessage(code, &meaning, nullptr);
    std::string detail = raw + (meaning ? std::string(" (") + meaning + ")" : std::string());
    if (last_petsc_failure.code == code && !last_petsc_failure.message.empty())
        detail += ": " + last_petsc_failure.message;
    const std::string& why = last_petsc_failure.message;
    // MUMPS's INFOG(1) -8, -9, -11, -13, -14, -17, -19, -20: workspace or memory
    // (MUMPS 5 users' guide, section 8); PETSc's own allocations: error 55.
    const bool memory = code == PETSC_ERR_MEM || mentions(why, "INFOG(1)=-9") || mentions(why, "INFOG(1)=-13") ||
                        mentions(why, "INFOG(1)=-8") || mentions(why, "INFOG(1)=-19") ||
                        mentions(why, "INFOG(1)=-20") || mentions(why, "INFOG(1)=-17") ||
                        mentions(why, "INFOG(1)=-14") || mentions(why, "INFOG(1)=-11") ||
                        mentions(why, "Memory requested") || mentions(why, "Out of memory");
    if (memory) return coremodal::out_of_memory_text() + " [" + detail + "]";
    if (code == PETSC_ERR_NOT_CONVERGED)
        return "the eigensolver did not converge [" + detail +
               "]; raise [analysis] max_iterations, or look in `coremodal check CASE` for a support or part far "
               "stiffer or softer than the rest of the model";
    constexpr int kArgumentErrors[] = {PETSC_ERR_ARG_SIZ,         PETSC_ERR_ARG_IDN,        PETSC_ERR_ARG_WRONG,
                                       PETSC_ERR_ARG_OUTOFRANGE,  PETSC_ERR_ARG_CORRUPT,    PETSC_ERR_ARG_BADPTR,
                                       PETSC_ERR_ARG_NOTSAMETYPE, PETSC_ERR_ARG_NOTSAMECOMM, PETSC_ERR_ARG_WRONGSTATE,
                                       PETSC_ERR_ARG_INCOMP,      PETSC_ERR_ARG_NULL,       PETSC_ERR_ARG_UNKNOWN_TYPE,
                                       PETSC_ERR_ARG_TYPENOTSET,  PETSC_ERR_USER_INPUT};
    if (std::find(std::begin(kArgumentErrors), std::end(kArgumentErrors), code) != std::end(kArgumentErrors))
        return "a solver option or a value handed to the solver is not valid [" + detail +
               "]; check the PETSc options (-name value) given after the command, and the case's values "
               "(`coremodal check CASE`)";
    return "the solver library failed [" + detail +
           "]; check the case (`coremodal check CASE`) for values far outside their plausible range and "
           "rerun; if it persists, report it with the case file and this message";
}

int report_error(const char* kind, const std::string& what) {
    coremodal::wait_if_interrupted();  // an error the interrupt's clean-up caused is no news
    int mpi_up = 0;
    MPI_Initialized(&mpi_up);
    if (!mpi_up || coremodal::mpi_rank() == 0) std::cerr << "coremodal: " << kind << what << std::endl;
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

int run_guarded(const coremodal::Command& command, const std::function<void()>& before = [] {}) {
    try {
        before();
        return command.run();
    } catch (const coremodal::InputError& e) {
        return report_error("error: ", e.what());
    } catch (const coremodal::SolveError& e) {
        return report_error("solve failed: ", e.what());
    } catch (const std::bad_alloc&) {
        return report_error("error: ", coremodal::out_of_memory_text());
    } catch (const std::exception& e) {
        const std::string what = e.what();
        if (what.rfind("PETSc error ", 0) == 0) return report_error("solve failed: ", explain_petsc_error(what));
        return report_error("", what);
    }
}

// Out of memory where no try block can catch it: gmsh's static initializers
// allocate while the libraries load, before main(), and under a tight
// address-space limit (ulimit -v) their std::bad_alloc would end in
// std::terminate ("terminate called ...", exit 134); a thread's likewise.
// The handler says what happened; installed from the executable's preinit
// array, which runs before any library's initializers.
[[noreturn]] void terminate_with_a_reason() {
    // The exception's type without rethrowing it: a rethrow allocates, and
    // memory is what is missing.
    const std::type_info* type = abi::__cxa_current_exception_type();
    if (type && (*type == typeid(std::bad_alloc) || *type == typeid(std::bad_array_new_length))) {
        std::string text;
        try {
            text = "coremodal: error: " + coremodal::out_of_memory_text() + "\n";
        } catch (...) {
        }
        static const char fallback[] =
            "coremodal: error: out of memory while starting (loading gmsh, PETSc, MPI and OpenBLAS); raise the "
            "address-space limit (ulimit -v) or the job's memory\n";
        [[maybe_unused]] const ssize_t written =
            text.empty() ? ::write(2, fallback, sizeof fallback - 1) : ::write(2, text.data(), text.size());
        ::_exit(1);
    }
    std::abort();
}

// The least address space a run must have left once the libraries are up:
// OpenBLAS takes a 128 MB buffer (and malloc a 64 MB arena for its thread) at
// its first call and, when that allocation fails, retries it forever, a hang
// at 100 % CPU (issue 33: case 08 under ulimit -v 600000). Measured: the
// smallest case (tests' tiny tube) at the harmonic level peaks ~300 MB above
// the address space mapped at start.
constexpr double kLeastHeadroomMb = 400;

// What the libraries' initializers, MPI and PETSc add to the address space
// between the preinit array and the first check (require_address_space), on
// one BLAS thread. Measured (case 01, no limit): VmSize 255 MB at preinit,
// 374 MB at the check.
constexpr double kStartupMb = 120;

// Before any library's initializer (the executable's preinit array): the
// terminate handler above, and no more OpenBLAS threads than the address-space
// limit affords (common/blas_threads.hpp: why).
extern "C" void before_libraries_start(int, char** argv, char** envp) {
    std::set_terminate(terminate_with_a_reason);
    coremodal::fit_blas_threads_to_address_space(argv, envp, kStartupMb + kLeastHeadroomMb);
}
__attribute__((section(".preinit_array"), used)) void (*const preinit_before_libraries)(int, char**, char**) =
    before_libraries_start;

// Refuses a run whose address-space limit leaves less than kLeastHeadroomMb;
// says when the limit took BLAS threads away.
void require_address_space() {
    if (const std::string note = coremodal::blas_threads_note(); !note.empty() && coremodal::mpi_rank() == 0)
        std::cerr << "coremodal: note: " << note << std::endl;
    const std::optional<coremodal::AddressSpace> space = coremodal::address_space_limit();
    if (!space || space->headroom_mb() >= kLeastHeadroomMb) return;
    throw coremodal::SolveError(coremodal::out_of_memory_text(
        space->used_mb + kLeastHeadroomMb, "the libraries loaded (" + std::to_string(long(space->used_mb)) +
                                               " MB) and the least a run takes beside them"));
}

// A command without PETSc has no work to share among MPI ranks: under
// mpirun each rank would run it whole and write the same folder.
int run_without_petsc(const coremodal::Command& chosen) {
    if (launched_processes() > 1) {
        if (launched_rank() == 0)
            std::cerr << "coremodal: error: `coremodal " << chosen.cli->get_name() << "` runs in one process ("
                      << launched_processes() << " MPI ranks would each run it and write the same output); run "
                      << "it without mpirun" << std::endl;
        // Only rank 0 exits 1 (the job's status): mpirun ends the whole
        // job at the first non-zero exit, which could stop rank 0 before
        // it has said why (seen in scripts/failure_injection.sh --quick).
        return launched_rank() == 0 ? 1 : 0;
    }
    const int status = run_guarded(chosen);
    coremodal::wait_if_interrupted();
    return status;
}

// PETSc and SLEPc started with their own options (`petsc_arguments`), the
// command run, and both finished.
int run_with_petsc(const coremodal::Command& chosen, std::vector<std::string>& petsc_arguments) {
    auto petsc = coremodal::c_strings(petsc_arguments);
    int petsc_argc = static_cast<int>(petsc_arguments.size());
    char** petsc_argv = petsc.data();
    coremodal::IsolatedMpiSingleton isolated;          // common/mpi_start.hpp: why
    coremodal::MpiSharedMemoryFolder shared_memory;    // ... and why
    if (SlepcInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr)) return 2;
    isolated.started();
    shared_memory.started();
    // PETSc errors become exceptions with coremodal's message; no tracebacks.
    PetscPushErrorHandler(remember_petsc_error, nullptr);
    coremodal::install_interrupt_handling();  // again: PETSc has put its own SIGTERM handler in place
    const int status = run_guarded(chosen, require_address_space);
    coremodal::wait_if_interrupted();
    PetscPopErrorHandler();  // PETSc's -malloc_dump lists the handler's 32 bytes otherwise
    SlepcFinalize();
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    coremodal::start_with_fast_memory_and_kernels(argv);  // first: it may start the program again
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
    return chosen->needs_petsc ? run_with_petsc(*chosen, args.petsc) : run_without_petsc(*chosen);
}
