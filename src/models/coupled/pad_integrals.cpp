#include "models/coupled/pad_integrals.hpp"

#include <cmath>

namespace coremodal {

double arcs_cos_integral(const std::vector<Arc>& arcs, int p) {
    double sum = 0;
    for (const Arc& a : arcs) sum += p == 0 ? a.to - a.from : (std::sin(p * a.to) - std::sin(p * a.from)) / p;
    return sum;
}

double arcs_sin_integral(const std::vector<Arc>& arcs, int p) {
    double sum = 0;
    if (p == 0) return 0;
    for (const Arc& a : arcs) sum += (std::cos(p * a.from) - std::cos(p * a.to)) / p;
    return sum;
}

namespace {

// A trig factor sign * (cos or sin)(n theta).
struct Factor {
    double sign;
    bool is_cos;
    int n;
};

Factor factor_of(HarmonicFamily h, int component) {
    const bool tangential = component == 1;
    if (h.n == 0) return {tangential ? -1.0 : 1.0, true, 0};
    if (h.family == Family::cos) return tangential ? Factor{-1, false, h.n} : Factor{1, true, h.n};
    return tangential ? Factor{1, true, h.n} : Factor{1, false, h.n};
}

}  // namespace

double trig_factor(HarmonicFamily h, int component, double theta) {
    const Factor f = factor_of(h, component);
    return f.sign * (f.is_cos ? std::cos(f.n * theta) : std::sin(f.n * theta));
}

double pad_integral(const std::vector<Arc>& arcs, HarmonicFamily a, HarmonicFamily b, int component) {
    const Factor f = factor_of(a, component), g = factor_of(b, component);
    const int d = f.n - g.n, s = f.n + g.n;
    double value;
    if (f.is_cos && g.is_cos)  // cos x cos y = (cos(x - y) + cos(x + y)) / 2
        value = (arcs_cos_integral(arcs, d) + arcs_cos_integral(arcs, s)) / 2;
    else if (!f.is_cos && !g.is_cos)  // sin x sin y = (cos(x - y) - cos(x + y)) / 2
        value = (arcs_cos_integral(arcs, d) - arcs_cos_integral(arcs, s)) / 2;
    else if (f.is_cos)  // cos x sin y = (sin(x + y) - sin(x - y)) / 2
        value = (arcs_sin_integral(arcs, s) - arcs_sin_integral(arcs, d)) / 2;
    else  // sin x cos y = (sin(x + y) + sin(x - y)) / 2
        value = (arcs_sin_integral(arcs, s) + arcs_sin_integral(arcs, d)) / 2;
    value *= f.sign * g.sign;
    return std::abs(value) < kVanishingIntegral * 2 * M_PI ? 0.0 : value;
}

}  // namespace coremodal
