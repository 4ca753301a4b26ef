// The least-squares power law of {16}-{20} and S_log of {24}, against
// hand calculations.
#include "durability/power_law_fit.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

TEST_CASE("points on a power law give back its b0 and b1 and no scatter", "[durability][fit]") {
    std::vector<double> x{0.5, 1, 3, 10, 40}, y;
    for (double xi : x) y.push_back(25.0 * std::pow(xi, -0.15));
    const PowerLawFit fit = fit_power_law(x, y);
    CHECK(fit.b0 == Approx(25.0).epsilon(1e-12));
    CHECK(fit.b1 == Approx(-0.15).epsilon(1e-12));
    CHECK(fit.s_log == Approx(0).margin(1e-12));
    CHECK(fit.weight(20) == Approx(25.0 * std::pow(20, -0.15)).epsilon(1e-12));
}

TEST_CASE("b1, b0 and S_log follow {18}, {19}, {20} and {24} by hand", "[durability][fit]") {
    // log10 x = 0, 1, 2; log10 y = 2, 1.9, 1.7 (y = 100, 79.43, 50.12).
    const PowerLawFit fit = fit_power_law({1, 10, 100}, {100, std::pow(10, 1.9), std::pow(10, 1.7)});
    // {18}: n Σxy - Σx Σy = 3 (0 + 1.9 + 3.4) - 3 (5.6) = -0.9; n Σx² - (Σx)² = 3 (5) - 9 = 6.
    CHECK(fit.b1 == Approx(-0.15).epsilon(1e-12));
    // {19}: mean log y - b1 mean log x = 5.6/3 + 0.15 = 2.016667.
    CHECK(fit.log_b0 == Approx(5.6 / 3 + 0.15).epsilon(1e-12));
    CHECK(fit.b0 == Approx(std::pow(10.0, 5.6 / 3 + 0.15)).epsilon(1e-12));  // {20}
    // Residuals -1/60, +1/30, -1/60; {24}: sqrt((1/3600 + 4/3600 + 1/3600)/(3 - 2)).
    CHECK(fit.log_residuals[1] == Approx(1.0 / 30).epsilon(1e-10));
    CHECK(fit.s_log == Approx(std::sqrt(6.0 / 3600)).epsilon(1e-10));
}
