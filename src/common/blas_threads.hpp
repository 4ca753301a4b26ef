// How many threads OpenBLAS runs: as many as the address space affords, and
// one for a stretch of code.
#pragma once

#include <string>

namespace coremodal {

// OpenBLAS starts its threads while it loads, and each thread at once takes
// its buffer (128 MB) and glibc a malloc arena for it (64 MB). When an
// address-space limit (ulimit -v, RLIMIT_AS) refuses them, OpenBLAS retries
// the allocation forever: a thread at 100 % CPU through the run and a hang at
// exit, where OpenBLAS waits for that thread (issue 33: case 08 under
// 600 MB, case 01 under 400 MB). The number of threads can only be chosen
// before OpenBLAS loads, through OPENBLAS_NUM_THREADS, and the environment
// cannot be changed before the libraries' initializers run (the C library's
// own initializer puts back the environment the process started with). So
// when the limit leaves room for fewer threads than OpenBLAS would start
// (each needs kPerThreadMb beside `least_headroom_mb`, what the run needs
// without them), this executes the program again, at once, with
// OPENBLAS_NUM_THREADS lowered; it returns when nothing needs to change.
// Called from the executable's preinit array (main.cpp) with the arguments
// and environment the program started with; uses only the C library.
void fit_blas_threads_to_address_space(char** argv, char** envp, double least_headroom_mb);

// What fit_blas_threads_to_address_space did, for the run's output ("BLAS on
// 1 thread instead of 2: ..."); empty when it left the count as it was.
std::string blas_threads_note();

// BLAS on one thread for a stretch of code. SLEPc's Krylov methods call
// level-2 BLAS (dgemv) on tall, thin blocks thousands of times; OpenBLAS's
// threads for such calls cost more than they save, and on a loaded machine
// far more: the quadratic solver's BVMultVec took 79 s on two threads beside
// a compile and 1.3 s on one (case 12 at the harmonic level, -log_view).
// The large dense kernels of a factorisation keep both threads: only the
// code inside the guard runs on one. OpenBLAS is looked up at run time;
// with another BLAS the guard does nothing.
class SingleThreadBlas {
public:
    SingleThreadBlas();
    ~SingleThreadBlas();
    SingleThreadBlas(const SingleThreadBlas&) = delete;
    SingleThreadBlas& operator=(const SingleThreadBlas&) = delete;

private:
    int previous_ = 0;  // 0: nothing to restore
};

}  // namespace coremodal
