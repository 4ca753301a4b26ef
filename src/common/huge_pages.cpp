#include "common/huge_pages.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <utility>
#include <vector>

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

// What OpenBLAS's SkylakeX kernels use.
bool processor_has_avx512() {
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
}

// The variables set for the start again, each with its value before (none: unset).
using Undo = std::vector<std::pair<const char*, std::optional<std::string>>>;

// Sets name=value, remembering the value before in `undo`.
bool set_remembering(const char* name, const std::string& value, Undo& undo) {
    const char* before = std::getenv(name);
    undo.emplace_back(name, before ? std::optional<std::string>(before) : std::nullopt);
    return setenv(name, value.c_str(), 1) == 0;
}

}  // namespace

std::optional<std::string> huge_page_tunables(const char* given, std::string_view policy, bool limited) {
    const std::string tunables = given ? given : "";
    if (tunables.find(kTunable) != std::string::npos || policy.find("[madvise]") == std::string_view::npos ||
        limited)
        return std::nullopt;
    return (tunables.empty() ? "" : tunables + ":") + std::string(kTunable) + "=1";
}

std::optional<std::string> blas_coretype(const char* given, bool avx512) {
    if (given || !avx512) return std::nullopt;
    return "SkylakeX";
}

void start_with_fast_memory_and_kernels(char** argv) {
    if (mpi_launched()) return;
    const std::optional<std::string> tunables =
        huge_page_tunables(std::getenv("GLIBC_TUNABLES"), huge_page_policy(), address_space_limited());
    const std::optional<std::string> coretype = blas_coretype(std::getenv("OPENBLAS_CORETYPE"), processor_has_avx512());
    if (!tunables && !coretype) return;
    Undo undo;
    if ((!tunables || set_remembering("GLIBC_TUNABLES", *tunables, undo)) &&
        (!coretype || set_remembering("OPENBLAS_CORETYPE", *coretype, undo)))
        execv("/proc/self/exe", argv);
    // Not started again: go on as we are, the environment as it was.
    for (const auto& [name, before] : undo) {
        if (before) setenv(name, before->c_str(), 1);
        else unsetenv(name);
    }
}

}  // namespace coremodal
