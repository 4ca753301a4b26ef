// Before MPI starts in a process no launcher started (no mpirun): Open MPI
// then makes the process a "singleton", and by default spawns a helper
// daemon (orted) for it, which costs every run about 0.4 s (a beam-level
// run of case 02: 1.70 s wall against 1.32 s isolated, 2026-11-26). coremodal
// never spawns processes through MPI, so an isolated singleton loses
// nothing. Under a launcher, or when the user has set the parameter, nothing
// changes.
#pragma once

namespace coremodal {

void prefer_isolated_mpi_singleton();

}  // namespace coremodal
