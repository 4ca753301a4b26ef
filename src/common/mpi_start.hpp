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

#include <filesystem>
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


// Open MPI's shared-memory transport (btl vader) keeps one file per rank in
// /dev/shm (vader_segment.<host>.<uid>.<job>.<rank>, 4 MB each) and removes
// them at MPI_Finalize, or mpirun does when it sees a rank die; a job killed
// whole with SIGKILL (a batch system's hard limit, kill -9 of the process
// group) leaves them, named by no process (issue 33, item 10: two 4 MB files
// after `kill -9` of `mpirun -n 2 coremodal run ...`). Under a launcher, each
// rank puts its file in a folder of its own, /dev/shm/coremodal-mpi-<pid>
// (OMPI_MCA_btl_vader_backing_directory; its peers find the file by the path
// MPI tells them), removed when the rank ends or is interrupted; and every
// coremodal that starts MPI first removes such folders of processes that are
// gone (common/process_folders.hpp). Without a launcher there is no peer and
// no file; a backing directory the user has set is left as it is.
class MpiSharedMemoryFolder {
public:
    MpiSharedMemoryFolder();   // before MPI_Init / SlepcInitialize
    void started();            // after: the variable is unset again
    ~MpiSharedMemoryFolder();  // after MPI_Finalize / SlepcFinalize: the folder removed
    MpiSharedMemoryFolder(const MpiSharedMemoryFolder&) = delete;
    MpiSharedMemoryFolder& operator=(const MpiSharedMemoryFolder&) = delete;

    // Where the folders are ("/dev/shm") and their names' prefix.
    static constexpr const char* kParent = "/dev/shm";
    static constexpr const char* kPrefix = "coremodal-mpi-";

private:
    std::filesystem::path folder_;  // empty: none made
    bool variable_set_ = false;
};

}  // namespace coremodal
