// Before MPI starts in a process no launcher started (no mpirun): Open MPI
// then makes the process a "singleton", and by default spawns a helper
// daemon (orted) for it, which costs every run about 0.5 s (a beam-level
// run of case 02: 1.65 s wall against 1.07 s isolated, 2026-11-26). coremodal
// never spawns processes through MPI, so an isolated singleton loses
// nothing. Isolated singletons all share one session directory name
// (jf.0/1), which one process's finalize can remove under another's start
// (seen once in a test run: "mkdir ... /tmp/ompi.<host>.0/jf.0/1: No such
// file or directory"), so no session directory is made: a singleton has no
// peer to share memory with. Under a launcher, or for a parameter the user
// has set, nothing changes; once MPI has started the variables are taken
// back, so that a child started later (mpirun in a test, a study worker)
// sees the user's environment.
#pragma once

#include <string>
#include <vector>

namespace coremodal {

class IsolatedMpiSingleton {
public:
    IsolatedMpiSingleton();   // before MPI_Init / SlepcInitialize
    void started();           // after: the variables set are unset again
private:
    std::vector<std::string> set_;
};

}  // namespace coremodal
