#include "common/mpi_start.hpp"

#include "common/process_folders.hpp"
#include "common/signals.hpp"

#include <unistd.h>

#include <cstdlib>
#include <initializer_list>

namespace coremodal {
namespace {

constexpr const char* kBackingDirectory = "OMPI_MCA_btl_vader_backing_directory";

// Whether an MPI launcher (mpirun/mpiexec: Open MPI, PMIx, MPICH's Hydra)
// started this process: it sets these in every process it starts.
bool launched() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(name)) return true;
    return false;
}

}  // namespace

IsolatedMpiSingleton::IsolatedMpiSingleton() {
    if (launched()) return;
    // pml ob1: a singleton has no peer, and Open MPI's default probes the
    // cm layer's interconnect libraries (PSM, PSM2: each calibrates its clock
    // pinned to one core for 0.1 s), which made MPI_Init 0.25 s instead of
    // 0.05 s (a bare MPI_Init, measured 2026-11-29) in every run and test.
    for (const auto& [name, value] : {std::pair<const char*, const char*>{"OMPI_MCA_ess_singleton_isolated", "1"},
                                      {"OMPI_MCA_orte_create_session_dirs", "0"},
                                      {"OMPI_MCA_pml", "ob1"}}) {
        if (std::getenv(name)) continue;  // the user's
        setenv(name, value, 1);
        set_.push_back(name);
    }
}

void IsolatedMpiSingleton::started() {
    for (const std::string& name : set_) unsetenv(name.c_str());
    set_.clear();
}

MpiSharedMemoryFolder::MpiSharedMemoryFolder() {
    std::error_code ec;
    if (!std::filesystem::is_directory(kParent, ec)) return;
    remove_folders_of_dead_processes(kParent, kPrefix);
    if (!launched() || std::getenv(kBackingDirectory)) return;
    const std::filesystem::path folder = process_folder(kParent, kPrefix, ::getpid());
    std::filesystem::remove_all(folder, ec);  // a folder of an earlier process of this number
    if (!std::filesystem::create_directory(folder, ec) || ec) return;  // Open MPI's default then
    std::filesystem::permissions(folder, std::filesystem::perms::owner_all, ec);
    folder_ = folder;
    try {
        remove_on_interrupt(folder_);
    } catch (const Interrupted&) {
        // The interrupt is being handled and ends the process; the next run removes the folder.
    }
    variable_set_ = ::setenv(kBackingDirectory, folder_.c_str(), 1) == 0;
}

void MpiSharedMemoryFolder::started() {
    if (variable_set_) ::unsetenv(kBackingDirectory);
    variable_set_ = false;
}

MpiSharedMemoryFolder::~MpiSharedMemoryFolder() {
    if (folder_.empty()) return;
    std::error_code ec;
    std::filesystem::remove_all(folder_, ec);
    keep_on_interrupt(folder_);
}

}  // namespace coremodal
