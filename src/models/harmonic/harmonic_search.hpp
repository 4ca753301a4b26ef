// The walk over circumferential wave numbers that both harmonic searches
// take (the harmonic level's modes at rest, models/harmonic/harmonic_level;
// the window of a spinning scene, models/harmonic/rotating_harmonics):
// n = 0, 1, 2, ... each asked for its modes below the edge found so far.
//
// Harmonics above those with modes below the edge are checked by their
// inertia (none below it) and their lowest eigenvalue. The lowest eigenvalue
// of a tube's harmonic falls with n while the membrane dominates and rises
// once ring bending (~n^4) does, so two empty harmonics in a row whose
// lowest eigenvalue rises from the one to the next end the search
// (docs/theory/harmonic.md).
#pragma once

#include "assembly/operator_set.hpp"
#include "eigensolve/modal_solver.hpp"

#include <functional>
#include <string>

namespace coremodal {

inline constexpr int kEmptyHarmonicsToStop = 2;

// What one harmonic held.
struct HarmonicVisit {
    bool has_modes = false;  // any below the edge
    double lowest = 0;       // its lowest eigenvalue, when it has none
};

// Calls visit(n) for n = 0, 1, 2, ... until the rule above stops it;
// throws SolveError(beyond_last()) when n would pass kMaxHarmonic.
void walk_harmonics(const std::function<HarmonicVisit(int n)>& visit, const std::function<std::string()>& beyond_last);

// The lowest eigenvalue of a problem with none below the edge: one verified
// mode, its inertia count proving it the lowest (the band of `request` is
// dropped).
double lowest_eigenvalue(const OperatorSet& operators, SolveRequest request);

}  // namespace coremodal
