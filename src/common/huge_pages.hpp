// The heap on transparent huge pages (2 MiB), where the kernel grants them
// on request. The solid level's one factorization writes gigabytes of fresh
// memory (the 540 k-DOF model: a 6.8 GB factor, its fronts and the
// assembled matrices); with 4 KiB pages the kernel takes a fault and zeroes
// a page for every 4 KiB touched, a quarter of the numeric factorization's
// time on a virtual machine (bench/results/log.md, "Huge pages for the
// heap, and what did not pay"; docs/performance.md).
//
// glibc (2.35 and later) madvises its heap for huge pages when the tunable
// glibc.malloc.hugetlb=1 is set, and reads tunables only when a program
// starts: so the program starts itself again with it, once, before anything
// else (no thread, no MPI, no file open yet). Nothing is done when the
// tunable is already given (a user's glibc.malloc.hugetlb=0 keeps 4 KiB
// pages), when the kernel gives huge pages to every mapping anyway
// ("always") or to none ("never"), under an address-space limit (ulimit -v:
// common/blas_threads.hpp budgets it), under an MPI launcher (a rank that
// starts again before MPI_Init hangs mpirun: give the tunable with
// `mpirun -x GLIBC_TUNABLES=glibc.malloc.hugetlb=1`), or when the start
// fails (the run goes on with 4 KiB pages).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace coremodal {

// The GLIBC_TUNABLES to start again with, from the ones `given` (null: none),
// the kernel's policy line (/sys/kernel/mm/transparent_hugepage/enabled) and
// whether an address-space limit is set; none when nothing is to be done.
std::optional<std::string> huge_page_tunables(const char* given, std::string_view policy, bool limited);

// Returns only when the program goes on as it is; otherwise argv starts again.
void start_with_huge_pages(char** argv);

}  // namespace coremodal
