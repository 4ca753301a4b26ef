// BLAS on one thread for a stretch of code. SLEPc's Krylov methods call
// level-2 BLAS (dgemv) on tall, thin blocks thousands of times; OpenBLAS's
// threads for such calls cost more than they save, and on a loaded machine
// far more: the quadratic solver's BVMultVec took 79 s on two threads beside
// a compile and 1.3 s on one (case 12 at the harmonic level, -log_view).
// The large dense kernels of a factorisation keep both threads: only the
// code inside the guard runs on one. OpenBLAS is looked up at run time;
// with another BLAS the guard does nothing.
#pragma once

namespace coremodal {

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
