#include "durability/power_law_fit.hpp"

#include "common/error.hpp"

#include <cmath>

namespace coremodal {

double PowerLawFit::log_weight(double x) const { return log_b0 + b1 * std::log10(x); }

double PowerLawFit::weight(double x) const { return std::pow(10.0, log_weight(x)); }

PowerLawFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y) {
    COREMODAL_ASSERT(x.size() == y.size() && x.size() >= 3);
    PowerLawFit fit;
    fit.n = static_cast<int>(x.size());
    std::vector<double> lx(x.size()), ly(y.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        COREMODAL_ASSERT(x[i] > 0 && y[i] > 0);
        lx[i] = std::log10(x[i]);
        ly[i] = std::log10(y[i]);
    }
    double mean_ly = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        fit.mean_log_x += lx[i] / fit.n;
        mean_ly += ly[i] / fit.n;
    }
    // {18} in centred form: the same b1, without the cancellation of
    // n Σ xy − Σx Σy when the log10 x are large and alike.
    double sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        fit.sxx += (lx[i] - fit.mean_log_x) * (lx[i] - fit.mean_log_x);
        sxy += (lx[i] - fit.mean_log_x) * (ly[i] - mean_ly);
    }
    COREMODAL_ASSERT(fit.sxx > 0);
    fit.b1 = sxy / fit.sxx;
    fit.log_b0 = mean_ly - fit.b1 * fit.mean_log_x;  // {19}
    fit.b0 = std::pow(10.0, fit.log_b0);            // {20}
    double sum_r2 = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double r = ly[i] - fit.log_weight(x[i]);
        fit.log_residuals.push_back(r);
        sum_r2 += r * r;
    }
    fit.s_log = std::sqrt(sum_r2 / fit.degrees_of_freedom());  // {24}
    return fit;
}

}  // namespace coremodal
