#include "eigensolve/band_edge.hpp"

#include "eigensolve/tolerances.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

int reported_count(const std::vector<double>& lambdas, int wanted, double scale) {
    int n = std::min<int>(wanted, lambdas.size());
    while (n > 0 && n < int(lambdas.size()) &&
           lambdas[n] - lambdas[n - 1] <= kClusterTolerance * std::max(std::abs(lambdas[n - 1]), scale))
        ++n;
    return n;
}

double check_point(const std::vector<double>& lambdas, int n_report, double scale) {
    const double last = lambdas[n_report - 1];
    return n_report < int(lambdas.size()) ? 0.5 * (last + lambdas[n_report])
                                          : last + kClusterTolerance * std::max(std::abs(last), scale);
}

}  // namespace coremodal
