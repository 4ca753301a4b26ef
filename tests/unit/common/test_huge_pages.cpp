// The heap on transparent huge pages (common/huge_pages.hpp): when the
// program asks glibc for them, and that a run does.
#include "common/huge_pages.hpp"

#include <catch2/catch.hpp>

#include <sys/resource.h>

#include <cstdio>
#include <fstream>
#include <string>

using coremodal::huge_page_tunables;

TEST_CASE("Huge pages are asked for only where the kernel grants them on request", "[common][huge_pages]") {
    const char* madvise = "always [madvise] never";
    CHECK(huge_page_tunables(nullptr, madvise, false) == "glibc.malloc.hugetlb=1");
    // The user's other tunables kept, in front.
    CHECK(huge_page_tunables("glibc.malloc.arena_max=2", madvise, false) ==
          "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
    // Given already (by us, which ends the second start, or by the user, 0 to keep 4 KiB pages).
    CHECK_FALSE(huge_page_tunables("glibc.malloc.hugetlb=0", madvise, false));
    CHECK_FALSE(huge_page_tunables("glibc.malloc.hugetlb=1", madvise, false));
    // The kernel gives them to every mapping, to none, or has no such file.
    CHECK_FALSE(huge_page_tunables(nullptr, "[always] madvise never", false));
    CHECK_FALSE(huge_page_tunables(nullptr, "always madvise [never]", false));
    CHECK_FALSE(huge_page_tunables(nullptr, "", false));
    // Under ulimit -v the budget is counted in 4 KiB pages.
    CHECK_FALSE(huge_page_tunables(nullptr, madvise, true));
}

TEST_CASE("A run starts itself again with huge pages where the kernel grants them on request",
          "[common][huge_pages]") {
    std::ifstream policy_file("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string policy;
    std::getline(policy_file, policy);
    struct rlimit limit {};
    const bool limited = ::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
    if (policy.find("[madvise]") == std::string::npos || limited) {
        SUCCEED("this machine's policy is not madvise, or an address-space limit is set: nothing to start again");
        return;
    }
    // The program's own environment, as the kernel sees it after the start: `check` runs long
    // enough to be read (a case parsed, its mesh described) and prints nothing to stdout here.
    // Started without the tunables (this test program has them: tests/main.cpp).
    const std::string command = "cd " COREMODAL_SOURCE_DIR " && (env -u GLIBC_TUNABLES " COREMODAL_BINARY
                                " check cases/01-iso-free-free-76x15.toml > /dev/null 2>&1 & pid=$!; "
                                "for i in $(seq 40); do tr '\\0' '\\n' < /proc/$pid/environ 2>/dev/null "
                                "| grep '^GLIBC_TUNABLES=' && break; sleep 0.05; done; wait $pid)";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    std::string out;
    char buffer[256];
    while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
    CHECK(pclose(pipe) == 0);
    CHECK(out.find("GLIBC_TUNABLES=glibc.malloc.hugetlb=1") != std::string::npos);
}

TEST_CASE("OpenBLAS's AVX-512 kernels are chosen only where the processor has them and the user chose none",
          "[common][huge_pages]") {
    using coremodal::blas_coretype;
    CHECK(blas_coretype(nullptr, true) == "SkylakeX");
    // The user's choice stands, whatever it is (Haswell to compare, or a core OpenBLAS knows better).
    CHECK_FALSE(blas_coretype("Haswell", true));
    CHECK_FALSE(blas_coretype("", true));
    // Without AVX-512 the kernels would stop on an illegal instruction: OpenBLAS chooses.
    CHECK_FALSE(blas_coretype(nullptr, false));
}
