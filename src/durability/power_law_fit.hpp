// The power law of a core's winding–unwinding durability, y = b0 x^b1
// ({16}), fitted by least squares in log–log ({17}–{20}) with its residuals
// and their standard deviation S_log ({24}). M. Ilomäki, "On the durability
// of cores and rest roll dynamics"; the choices where the paper leaves room
// are in docs/how-to/durability.md.
//
// Logarithms are base 10 as in the paper ({20}: b0 = 10^log(b0)). Residuals
// are in log10 y (docs/how-to/durability.md, "Residuals in log y"): the scatter the
// paper's S_log ({24}) and reduced curves ({31}, {32}) describe.
#pragma once

#include <vector>

namespace coremodal {

struct PowerLawFit {
    int n = 0;                  // data points
    double b1 = 0;              // {18}: the slope in log–log (negative: fewer cycles at a heavier roll)
    double log_b0 = 0;          // {19}: log10 b0
    double b0 = 0;              // {20}: weight at x = 1 cycle, in the data's unit
    double mean_log_x = 0;      // the centroid of log10 x_i
    double sxx = 0;             // sum (log10 x_i - mean_log_x)^2
    double s_log = 0;           // {24}: standard deviation of the log10 residuals, n - 2 degrees of freedom
    std::vector<double> log_residuals;  // log10 y_i - log10 y(x_i)

    int degrees_of_freedom() const { return n - 2; }
    double log_weight(double x) const;  // {17}: log10 y(x)
    double weight(double x) const;      // {16}: y(x)
};

// The least-squares fit of log10 y on log10 x ({18}–{20}, {24}). Requires at
// least three points (two parameters and one degree of freedom for S_log),
// x > 0, y > 0 and two distinct x (the caller's reader says so to the user).
PowerLawFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace coremodal
