// Power-law fits y ~ a x^b: how run time and memory grow with the number of
// unknowns (coremodal converge).
#pragma once

#include <optional>
#include <vector>

namespace coremodal {

// Least-squares slope of log(y) against log(x): y ~ x^slope. Pairs with a
// non-positive value are left out; needs >= 2 remaining points with distinct
// x, else nullopt.
std::optional<double> power_law_exponent(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace coremodal
