#include "common/mpi_start.hpp"

#include <cstdlib>
#include <initializer_list>

namespace coremodal {

void prefer_isolated_mpi_singleton() {
    // Set by mpirun/mpiexec (Open MPI, PMIx, MPICH's Hydra) in every process it starts.
    for (const char* launched : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(launched)) return;
    setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
}

}  // namespace coremodal
