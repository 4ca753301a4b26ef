#include "common/warnings.hpp"

#include <mpi.h>

#include <iostream>

namespace coremodal {

void print_warnings(const std::vector<std::string>& warnings) {
    int mpi_on = 0;
    MPI_Initialized(&mpi_on);
    int rank = 0;
    if (mpi_on) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0) return;
    for (const std::string& w : warnings) std::cerr << "coremodal: warning: " << w << std::endl;
}

}  // namespace coremodal
