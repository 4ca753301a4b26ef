// Richardson extrapolation with an observed order: from values f(h) at three
// or more element sizes h, the limit f0 of f(h) = f0 + C h^p, the order p the
// values themselves show, and whether they are in the asymptotic range.
// coremodal converge uses it on frequencies of a refinement ladder
// (docs/validation/accuracy-vs-cost.md); the h need not have a constant ratio.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// Result of Richardson extrapolation f(h) = f0 + C h^p from three levels.
struct Richardson {
    bool extrapolated = false;  // false: f0 is the finest value, see note
    double order = 0;           // observed p (0 when not extrapolated)
    double f0 = 0;              // extrapolated value
    double error_estimate = 0;  // |f_finest - f0| (for oscillating sequences the largest change)
    bool asymptotic = false;    // order plausible, and consistent with the previous triple if there is one
    std::optional<double> previous_order;  // p from the triple one level coarser
    std::optional<double> previous_f0;     // f0 from that triple
    std::optional<double> f0_uncertainty;  // |f0 - previous_f0|: how well f0 itself is known
    std::string note;           // plain words for the report
};

// Plausible observed orders: quadratic elements give eigenvalue errors ~ h^4
// on smooth problems; stress singularities at clamp edges lower that towards 1
// or below (docs/validation/accuracy-vs-cost.md). Outside this range the levels are not in
// the asymptotic range and the report says so.
inline constexpr double kMinPlausibleOrder = 0.5;
inline constexpr double kMaxPlausibleOrder = 8.0;
// Two triples agree on the order when they differ by less than this fraction.
inline constexpr double kOrderConsistency = 0.25;
// Changes below this relative size are the eigen solver's round-off (its
// tolerance is 1e-10 on eigenvalues): such a mode has converged.
inline constexpr double kSolverNoise = 1e-9;
// The observed order is searched in [0, kMaxSearchedOrder]: far beyond any
// plausible order, so that an implausible one is still reported as such; a
// ratio beyond it extrapolates with this cap.
inline constexpr double kMaxSearchedOrder = 30;

// The observed order of three sizes h1 > h2 > h3 > 0 whose changes have the
// ratio (f1 - f2)/(f2 - f3) = `ratio`: the p that solves
// (h1^p - h2^p)/(h2^p - h3^p) = ratio, by bisection (the left side grows
// monotonically with p from ln(h1/h2)/ln(h2/h3) at p -> 0), capped at
// kMaxSearchedOrder. `ratio` must exceed the p -> 0 limit.
double observed_order(const double h[3], double ratio);

// Three levels, coarse to fine (h1 > h2 > h3 > 0): the observed order p, then
// f0 = f3 - C h3^p. Alternating, growing or vanishing changes are not
// extrapolated and say so in `note`.
Richardson richardson_three(const double h[3], const double f[3]);

// Extrapolation from the three finest of n >= 3 levels, with the previous
// triple's order and f0 for the consistency check when n >= 4.
Richardson richardson(const std::vector<double>& h, const std::vector<double>& f);

}  // namespace coremodal
