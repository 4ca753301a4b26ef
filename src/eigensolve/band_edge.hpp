// Where a solve's report ends and its completeness count is taken: one rule
// for the symmetric solver (modal_solver.cpp) and the gyroscopic ones
// (gyroscopic_solver.cpp, projected_gyroscopic.cpp), on eigenvalues
// lambda = omega^2 (rad^2/s^2) in ascending order, as found.
#pragma once

#include <vector>

namespace coremodal {

// The wanted count, extended so that every member of the last mode's cluster
// (eigenvalues within kClusterTolerance, tolerances.hpp) is reported too.
int reported_count(const std::vector<double>& lambdas, int wanted, double scale);

// The count's point: halfway into the gap after the last reported eigenvalue,
// or just above it when nothing was found beyond.
double check_point(const std::vector<double>& lambdas, int n_report, double scale);

}  // namespace coremodal
