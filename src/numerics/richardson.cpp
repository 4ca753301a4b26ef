#include "numerics/richardson.hpp"

#include "common/error.hpp"
#include "common/format.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// (h1^p - h2^p) / (h2^p - h3^p), which grows with p from
// ln(h1/h2)/ln(h2/h3) at p -> 0 to infinity.
double ratio_of_differences(const double h[3], double p) {
    return (std::pow(h[0], p) - std::pow(h[1], p)) / (std::pow(h[1], p) - std::pow(h[2], p));
}

}  // namespace

double observed_order(const double h[3], double ratio) {
    double lo = 0, hi = kMaxSearchedOrder;
    if (ratio_of_differences(h, hi) < ratio) {
        lo = hi;  // beyond any plausible order: extrapolate with the cap
    } else {
        for (int i = 0; i < 200 && hi - lo > 1e-13; ++i) {
            const double mid = 0.5 * (lo + hi);
            (ratio_of_differences(h, mid) < ratio ? lo : hi) = mid;
        }
    }
    return 0.5 * (lo + hi);
}

Richardson richardson_three(const double h[3], const double f[3]) {
    COREMODAL_ASSERT(h[0] > h[1] && h[1] > h[2] && h[2] > 0);
    Richardson r;
    const double d1 = f[0] - f[1], d2 = f[1] - f[2];
    const double scale = std::max({std::abs(f[0]), std::abs(f[1]), std::abs(f[2])});
    r.f0 = f[2];
    if (std::abs(d2) <= kSolverNoise * scale) {
        r.error_estimate = std::max(std::abs(d2), kSolverNoise * scale);
        r.asymptotic = true;
        r.note = "converged to solver precision";
        return r;
    }
    if (d1 * d2 <= 0) {
        r.error_estimate = std::max(std::abs(d1), std::abs(d2));
        r.note = "not monotone (the changes alternate in sign): no order; error estimate = largest change";
        return r;
    }
    const double target = d1 / d2;
    const double at_zero = std::log(h[0] / h[1]) / std::log(h[1] / h[2]);
    if (target <= at_zero) {
        r.error_estimate = std::abs(d2) * 10;  // no bound exists; a generous stand-in
        r.note = "changes do not shrink with h (order <= 0): not in the asymptotic range; "
                 "error estimate = 10 x the last change";
        return r;
    }
    const double p = observed_order(h, target);
    const double c = d2 / (std::pow(h[1], p) - std::pow(h[2], p));
    r.extrapolated = true;
    r.order = p;
    r.f0 = f[2] - c * std::pow(h[2], p);
    r.error_estimate = std::abs(f[2] - r.f0);
    r.asymptotic = p >= kMinPlausibleOrder && p <= kMaxPlausibleOrder;
    r.note = r.asymptotic ? "observed order " + formatted("%.2f", p)
                          : "observed order " + formatted("%.2f", p) + " outside [" + formatted("%.1f", kMinPlausibleOrder) +
                                ", " + formatted("%.0f", kMaxPlausibleOrder) + "]: not in the asymptotic range";
    return r;
}

Richardson richardson(const std::vector<double>& h, const std::vector<double>& f) {
    COREMODAL_ASSERT(h.size() == f.size() && h.size() >= 3);
    const std::size_t n = h.size();
    Richardson r = richardson_three(&h[n - 3], &f[n - 3]);
    if (n < 4) {
        if (r.extrapolated) r.note += "; only three levels: order not cross-checked";
        return r;
    }
    const Richardson previous = richardson_three(&h[n - 4], &f[n - 4]);
    if (previous.extrapolated) {
        r.previous_order = previous.order;
        r.previous_f0 = previous.f0;
    }
    if (!r.extrapolated) return r;
    if (previous.extrapolated) r.f0_uncertainty = std::abs(r.f0 - previous.f0);
    if (r.asymptotic && previous.extrapolated) {
        const bool consistent =
            std::abs(r.order - previous.order) <= kOrderConsistency * std::max(r.order, previous.order);
        if (!consistent) {
            r.asymptotic = false;
            r.note += "; the coarser triple gives " + formatted("%.2f", previous.order) +
                      ": order not settled, not yet asymptotic";
        } else {
            r.note += " (coarser triple " + formatted("%.2f", previous.order) + ")";
        }
    } else if (r.asymptotic) {
        r.asymptotic = false;
        r.note += "; the coarser triple has no order (" + previous.note + "): not yet asymptotic";
    }
    return r;
}

}  // namespace coremodal
