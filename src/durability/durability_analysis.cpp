#include "durability/durability_analysis.hpp"

#include "durability/quantiles.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// Points of the plotted curves per decade of cycles.
constexpr int kCurvePointsPerDecade = 20;

}  // namespace

std::vector<double> table_cycle_counts(double max_cycles) {
    std::vector<double> cycles{0.5};
    const double last = std::max(max_cycles, 10.0);
    for (double decade = 1;; decade *= 10)
        for (double step : {1.0, 2.0, 5.0}) {
            cycles.push_back(step * decade);
            if (step * decade >= last) return cycles;
        }
}

DurabilityAnalysis analyse_durability(const DurabilityData& data, double confidence,
                                      const std::vector<double>& probabilities) {
    DurabilityAnalysis a;
    a.fit = fit_power_law(data.cycles, data.weights);
    a.confidence = confidence;
    const int dof = a.fit.degrees_of_freedom();
    a.t2 = student_t_upper_limit(confidence, dof);
    a.h1 = chi_squared_lower_limit(confidence, dof);
    a.upper_sd_log = upper_standard_deviation(a.fit, confidence);
    a.intervals = parameter_intervals(a.fit, confidence);
    a.table_cycles = table_cycle_counts(*std::max_element(data.cycles.begin(), data.cycles.end()));
    for (double p : probabilities) {
        ProbabilityLimit limit{p, safety_factors(a.fit, confidence, p), {}};
        for (double x : a.table_cycles)
            limit.allowed_weights.push_back(std::pow(10.0, reduced_log_weight(a.fit, x, confidence, p)));
        a.limits.push_back(limit);
    }
    const double decades = std::log10(a.table_cycles.back() / a.table_cycles.front());
    const int n = static_cast<int>(std::ceil(decades * kCurvePointsPerDecade));
    for (int i = 0; i <= n; ++i) a.curve_cycles.push_back(a.table_cycles.front() * std::pow(10.0, decades * i / n));
    return a;
}

}  // namespace coremodal
