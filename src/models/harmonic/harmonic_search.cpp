#include "models/harmonic/harmonic_search.hpp"

#include "common/error.hpp"
#include "models/harmonic/harmonic_shapes.hpp"  // kMaxHarmonic

namespace coremodal {

void walk_harmonics(const std::function<HarmonicVisit(int n)>& visit, const std::function<std::string()>& beyond_last) {
    int empty_in_a_row = 0;
    double previous_lowest = 0;  // of the previous empty harmonic
    for (int n = 0;; ++n) {
        if (n > kMaxHarmonic) throw SolveError(beyond_last());
        const HarmonicVisit v = visit(n);
        if (v.has_modes) {
            empty_in_a_row = 0;
            continue;
        }
        const bool rising = empty_in_a_row > 0 && v.lowest > previous_lowest;
        previous_lowest = v.lowest;
        if (++empty_in_a_row >= kEmptyHarmonicsToStop && rising) return;
    }
}

double lowest_eigenvalue(const OperatorSet& operators, SolveRequest request) {
    request.n_modes = 1;
    request.lambda_min.reset();
    request.lambda_max.reset();
    return solve_modes(operators, request, [](const std::string&) {}).eigenvalues.at(0);
}

}  // namespace coremodal
