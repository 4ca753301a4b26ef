#include "durability/durability_limits.hpp"

#include "common/error.hpp"
#include "durability/quantiles.hpp"

#include <cmath>
#include <numbers>

namespace coremodal {

double reduction_factor(double p) {
    COREMODAL_ASSERT(p > 0 && p <= 0.5);
    return p == 0.5 ? 0.0 : normal_quantile(p);  // exactly 0 at the median, as Table 3 prints it
}

double safety_factor(double lambda, double s_relative) {
    const double reduced = 1 + lambda * s_relative;
    COREMODAL_ASSERT(reduced > 0);
    return 1 / reduced;
}

double mean_standard_error(const PowerLawFit& fit, double x) {
    const double d = std::log10(x) - fit.mean_log_x;
    return fit.s_log * std::sqrt(1.0 / fit.n + d * d / fit.sxx);
}

double confident_mean_log_weight(const PowerLawFit& fit, double x, double confidence) {
    const double t2 = student_t_upper_limit(confidence, fit.degrees_of_freedom());
    return fit.log_weight(x) - t2 * mean_standard_error(fit, x);
}

double upper_standard_deviation(const PowerLawFit& fit, double confidence) {
    const int dof = fit.degrees_of_freedom();
    const double h1 = chi_squared_lower_limit(confidence, dof);
    return std::sqrt(dof / h1) * fit.s_log;
}

double reduced_log_weight(const PowerLawFit& fit, double x, double confidence, double p) {
    return confident_mean_log_weight(fit, x, confidence) +
           reduction_factor(p) * upper_standard_deviation(fit, confidence);
}

SafetyFactors safety_factors(const PowerLawFit& fit, double confidence, double p) {
    SafetyFactors f;
    f.lambda = reduction_factor(p);
    f.upper_sd_log = upper_standard_deviation(fit, confidence);
    f.log_space = std::pow(10.0, -f.lambda * f.upper_sd_log);
    f.relative_deviation = std::numbers::ln10 * f.upper_sd_log;
    const double reduced = 1 + f.lambda * f.relative_deviation;
    f.paper_eq30 = reduced > 0 ? 1 / reduced : 0;
    return f;
}

namespace {

Band around(double centre, double half_width) { return {centre - half_width, centre + half_width}; }

double two_sided_t(const PowerLawFit& fit, double confidence) {
    return student_t_upper_limit((1 + confidence) / 2, fit.degrees_of_freedom());
}

}  // namespace

Band confidence_band(const PowerLawFit& fit, double x, double confidence) {
    return around(fit.log_weight(x), two_sided_t(fit, confidence) * mean_standard_error(fit, x));
}

Band prediction_band(const PowerLawFit& fit, double x, double confidence) {
    const double se = mean_standard_error(fit, x);
    return around(fit.log_weight(x), two_sided_t(fit, confidence) * std::sqrt(fit.s_log * fit.s_log + se * se));
}

ParameterIntervals parameter_intervals(const PowerLawFit& fit, double confidence) {
    const double t = two_sided_t(fit, confidence);
    const int dof = fit.degrees_of_freedom();
    ParameterIntervals p;
    p.b1 = around(fit.b1, t * fit.s_log / std::sqrt(fit.sxx));
    p.log_b0 = around(fit.log_b0, t * fit.s_log * std::sqrt(1.0 / fit.n + fit.mean_log_x * fit.mean_log_x / fit.sxx));
    const double tail = (1 - confidence) / 2;
    p.s_log = {fit.s_log * std::sqrt(dof / chi_squared_quantile(1 - tail, dof)),
               fit.s_log * std::sqrt(dof / chi_squared_quantile(tail, dof))};
    return p;
}

}  // namespace coremodal
