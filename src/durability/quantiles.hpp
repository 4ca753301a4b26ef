// The three distributions of Ilomäki's durability statistics, as quantiles
// from Boost.Math (never written by hand): Student's t for the confidence of
// the mean ({22}, {23}), χ² for the upper standard deviation ({25}, {26}) and
// the standard normal for the failure probability ({27}). M. Ilomäki, "On the
// durability of cores and rest roll dynamics" (docs/how-to/durability.md).
#pragma once

namespace coremodal {

// t2 of {23}: the t with P(T <= t2) = confidence for `dof` degrees of freedom.
// Requires 0 < confidence < 1 and dof >= 1.
double student_t_upper_limit(double confidence, int dof);

// h1 of {26}: the h with P(H >= h1) = confidence for a χ² variable with `dof`
// degrees of freedom (the lower (1 - confidence) quantile).
double chi_squared_lower_limit(double confidence, int dof);

// The χ² quantile: the h with P(H <= h) = p.
double chi_squared_quantile(double p, int dof);

// λ of {27}: the standard normal quantile, P(X <= λ) = p; requires 0 < p < 1.
double normal_quantile(double p);

}  // namespace coremodal
