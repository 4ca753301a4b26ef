#include "common/mpi_start.hpp"

#include <cstdlib>
#include <initializer_list>

namespace coremodal {

IsolatedMpiSingleton::IsolatedMpiSingleton() {
    // Set by mpirun/mpiexec (Open MPI, PMIx, MPICH's Hydra) in every process it starts.
    for (const char* launched : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(launched)) return;
    for (const auto& [name, value] : {std::pair<const char*, const char*>{"OMPI_MCA_ess_singleton_isolated", "1"},
                                      {"OMPI_MCA_orte_create_session_dirs", "0"}}) {
        if (std::getenv(name)) continue;  // the user's
        setenv(name, value, 1);
        set_.push_back(name);
    }
}

void IsolatedMpiSingleton::started() {
    for (const std::string& name : set_) unsetenv(name.c_str());
    set_.clear();
}

}  // namespace coremodal
