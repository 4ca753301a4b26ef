// Test runner: SLEPc (and so PETSc and MPI) is initialised once for all tests,
// so tests that assemble or solve can use PETSc objects directly.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <slepcsys.h>

#include "common/huge_pages.hpp"
#include "common/mpi_start.hpp"

int main(int argc, char** argv) {
    // The solver tests' heap on huge pages and OpenBLAS's kernels, as a run's
    // (common/huge_pages.hpp): first.
    coremodal::start_with_fast_memory_and_kernels(argv);
    // PETSc must not see Catch's options; give it none.
    int petsc_argc = 1;
    char** petsc_argv = argv;
    coremodal::IsolatedMpiSingleton isolated;  // common/mpi_start.hpp: why
    SlepcInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr);
    isolated.started();
    PetscPopSignalHandler();  // let Catch report crashes
    const int result = Catch::Session().run(argc, argv);
    SlepcFinalize();
    return result;
}
