// Ilomäki's Table 3 from its equations, and the fit's confidence statements
// checked by what they promise: over many synthetic data sets drawn from a
// known power law with log-normal scatter, the intervals hold the true
// values C of the time.
#include "durability/durability_limits.hpp"
#include "durability/power_law_fit.hpp"
#include "durability/quantiles.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace coremodal;

TEST_CASE("Table 3 is reproduced from equations {27} and {30}", "[durability][table3]") {
    // M. Ilomäki, "On the durability of cores and rest roll dynamics", Table 3,
    // as printed: lambda to 3 decimals, the safety factors to 3 decimals.
    const double lambda[] = {0.0, -2.326, -3.090, -3.719, -4.265, -4.753};
    const double printed[3][6] = {{1.0, 1.132, 1.183, 1.228, 1.271, 1.312},
                                  {1.0, 1.303, 1.447, 1.592, 1.774, 1.906},
                                  {1.0, 1.536, 1.864, 2.262, 2.776, 3.484}};
    for (int j = 0; j < 6; ++j) {
        const double l = reduction_factor(kTable3Probabilities[j]);
        INFO("P = " << kTable3Probabilities[j]);
        CHECK(l == Approx(lambda[j]).margin(0.0005));  // printed to 3 decimals
        for (int i = 0; i < 3; ++i) {
            INFO("S_Crelative = " << kTable3RelativeDeviations[i]);
            const double sf = safety_factor(l, kTable3RelativeDeviations[i]);
            // The one printed value that disagrees with {30}: 10 % at P = 1e-5
            // is 1/(1 - 4.265 0.10) = 1.744, printed 1.774 (two digits
            // swapped; docs/how-to/durability.md). The test follows the equation.
            const double expected = (i == 1 && j == 4) ? 1.744 : printed[i][j];
            CHECK(sf == Approx(expected).margin(0.0006));  // 3 decimals, lambda's rounding included
        }
    }
    CHECK(std::abs(safety_factor(reduction_factor(1e-5), 0.10) - 1.774) > 0.02);
}

TEST_CASE("the reduced curve is the confident mean lowered by lambda upper standard deviations", "[durability]") {
    const PowerLawFit fit = fit_power_law({0.5, 1, 2, 5, 10, 50, 100}, {30, 27, 26, 22, 21, 17, 16});
    const double c = 0.99, p = 1e-5, x = 7;
    const double expected = confident_mean_log_weight(fit, x, c) + normal_quantile(p) * upper_standard_deviation(fit, c);
    CHECK(reduced_log_weight(fit, x, c, p) == Approx(expected));
    // At P = 0.5 the reduced curve is the confident mean itself (lambda = 0).
    CHECK(reduced_log_weight(fit, x, c, 0.5) == Approx(confident_mean_log_weight(fit, x, c)));
    // {22} at the centroid: the mean lowered by t2 S/sqrt(n).
    const double centroid = std::pow(10.0, fit.mean_log_x);
    CHECK(fit.log_weight(centroid) - confident_mean_log_weight(fit, centroid, c) ==
          Approx(student_t_upper_limit(c, fit.n - 2) * fit.s_log / std::sqrt(fit.n)));
    // The safety factor of the reduced curve is constant in x.
    const SafetyFactors f = safety_factors(fit, c, p);
    for (double xi : {0.5, 3.0, 80.0})
        CHECK(std::pow(10.0, confident_mean_log_weight(fit, xi, c) - reduced_log_weight(fit, xi, c, p)) ==
              Approx(f.log_space));
}

namespace {

// One simulator campaign: n tests spread over 0.5 to 2000 cycles, log10 y
// from the true line plus normal scatter of sd s_log (log-normal in y).
struct Truth {
    double log_b0 = std::log10(30.0), b1 = -0.12, s_log = 0.04;
};
PowerLawFit synthetic_fit(const Truth& t, int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> log_x(std::log10(0.5), std::log10(2000.0));
    std::normal_distribution<double> scatter(0.0, t.s_log);
    std::vector<double> x, y;
    for (int i = 0; i < n; ++i) {
        const double lx = log_x(rng);
        x.push_back(std::pow(10.0, lx));
        y.push_back(std::pow(10.0, t.log_b0 + t.b1 * lx + scatter(rng)));
    }
    return fit_power_law(x, y);
}

bool inside(const Band& b, double v) { return b.lower <= v && v <= b.upper; }

}  // namespace

TEST_CASE("b0, b1 and S_log are recovered within their confidence intervals C of the time",
          "[durability][coverage]") {
    // 400 campaigns of 20 points, 95 % intervals: the count inside is
    // binomial(400, 0.95), standard deviation 4.4; 4 of them (±17.4, 0.044)
    // makes a false alarm rarer than 1 in 10^4 while an interval built on
    // the wrong degrees of freedom or quantile misses it.
    const Truth t;
    const double c = 0.95;
    const int n_seeds = 400;
    int b1_in = 0, b0_in = 0, s_in = 0, mean_below = 0, sd_above = 0;
    for (int seed = 1; seed <= n_seeds; ++seed) {
        const PowerLawFit fit = synthetic_fit(t, 20, seed);
        const ParameterIntervals iv = parameter_intervals(fit, c);
        b1_in += inside(iv.b1, t.b1);
        b0_in += inside(iv.log_b0, t.log_b0);
        s_in += inside(iv.s_log, t.s_log);
        // The one-sided statements of {22} and {25}: the confident mean at x
        // lies below the true mean, S_C above the true deviation, C of the time.
        mean_below += confident_mean_log_weight(fit, 10.0, c) <= t.log_b0 + t.b1 * 1.0;
        sd_above += upper_standard_deviation(fit, c) >= t.s_log;
    }
    const double tolerance = 4 * std::sqrt(c * (1 - c) / n_seeds);
    CHECK(double(b1_in) / n_seeds == Approx(c).margin(tolerance));
    CHECK(double(b0_in) / n_seeds == Approx(c).margin(tolerance));
    CHECK(double(s_in) / n_seeds == Approx(c).margin(tolerance));
    CHECK(double(mean_below) / n_seeds == Approx(c).margin(tolerance));
    CHECK(double(sd_above) / n_seeds == Approx(c).margin(tolerance));
}

TEST_CASE("the prediction band holds new tests C of the time", "[durability][coverage]") {
    const Truth t;
    const double c = 0.9;
    const int n_seeds = 400;
    std::mt19937 rng(7);
    std::normal_distribution<double> scatter(0.0, t.s_log);
    int held = 0;
    for (int seed = 1; seed <= n_seeds; ++seed) {
        const PowerLawFit fit = synthetic_fit(t, 12, 1000 + seed);
        const double new_test = t.log_b0 + t.b1 * std::log10(300.0) + scatter(rng);
        held += inside(prediction_band(fit, 300.0, c), new_test);
    }
    CHECK(double(held) / n_seeds == Approx(c).margin(4 * std::sqrt(c * (1 - c) / n_seeds)));
}
