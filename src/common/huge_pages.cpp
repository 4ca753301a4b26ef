#include "common/huge_pages.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

namespace coremodal {
namespace {

constexpr std::string_view kTunable = "glibc.malloc.hugetlb";

// The kernel's policy, e.g. "always [madvise] never" (the one in use in brackets).
std::string huge_page_policy() {
    std::ifstream policy("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string text;
    std::getline(policy, text);
    return text;
}

// An address-space limit (ulimit -v) is budgeted to the megabyte with 4 KiB
// pages (common/blas_threads.hpp); huge pages would round allocations up.
bool address_space_limited() {
    struct rlimit limit {};
    return ::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
}

// Started by an MPI launcher (Open MPI, PMIx, MPICH's Hydra): a rank that
// executes itself again before MPI_Init hangs the job (mpirun -n 2 of case
// 05, scripts/failure_injection.sh).
bool mpi_launched() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
        if (std::getenv(name)) return true;
    return false;
}

}  // namespace

std::optional<std::string> huge_page_tunables(const char* given, std::string_view policy, bool limited) {
    const std::string tunables = given ? given : "";
    if (tunables.find(kTunable) != std::string::npos || policy.find("[madvise]") == std::string_view::npos ||
        limited)
        return std::nullopt;
    return (tunables.empty() ? "" : tunables + ":") + std::string(kTunable) + "=1";
}

void start_with_huge_pages(char** argv) {
    const char* given = std::getenv("GLIBC_TUNABLES");
    if (mpi_launched()) return;
    const std::optional<std::string> with = huge_page_tunables(given, huge_page_policy(), address_space_limited());
    if (!with) return;
    const std::string before = given ? given : "";
    if (setenv("GLIBC_TUNABLES", with->c_str(), 1) != 0) return;
    execv("/proc/self/exe", argv);
    // Not started again: go on as we are, the environment as it was.
    if (given) setenv("GLIBC_TUNABLES", before.c_str(), 1);
    else unsetenv("GLIBC_TUNABLES");
}

}  // namespace coremodal
