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
//
// The same start sets OpenBLAS's kernels where the processor has AVX-512 and
// the user chose none (OPENBLAS_CORETYPE, read by OpenBLAS only as it
// loads): Debian 12's OpenBLAS 0.3.21 does not know AMD's Zen 4 and Zen 5
// and gives them its AVX2 (Haswell) kernels. On the Zen 5 machine of session
// 26 the SkylakeX kernels ran dgemm at 156-160 GFlop/s against 90-97 and
// sgemm at 345-376 against 184-197 (bench/kernel_rates.c), case 03 in
// 20.3-21.5 s against 25.0-28.2 and the 540 k-DOF model out of core in
// 116 s against 150, the same modes to 5e-12 (bench/results/log.md,
// "OpenBLAS's AVX-512 kernels"). Later OpenBLAS releases choose them there
// themselves; on Intel's AVX-512 processors they are what it chooses anyway.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace coremodal {

// The GLIBC_TUNABLES to start again with, from the ones `given` (null: none),
// the kernel's policy line (/sys/kernel/mm/transparent_hugepage/enabled) and
// whether an address-space limit is set; none when nothing is to be done.
std::optional<std::string> huge_page_tunables(const char* given, std::string_view policy, bool limited);

// The OPENBLAS_CORETYPE to start again with: "SkylakeX" (OpenBLAS's AVX-512
// kernels) when the processor has AVX-512 F, DQ, BW and VL and the user gave
// none (`given` null); none otherwise.
std::optional<std::string> blas_coretype(const char* given, bool avx512);

// Returns only when the program goes on as it is; otherwise argv starts again
// with the huge-page tunable and OpenBLAS's kernels above, once.
void start_with_fast_memory_and_kernels(char** argv);

}  // namespace coremodal
