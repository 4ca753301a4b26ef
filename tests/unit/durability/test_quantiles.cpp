// The quantiles of the durability statistics against values computed
// independently: mpmath 1.3 at 30 digits, by bisection on the regularized
// incomplete beta (Student's t), the regularized lower incomplete gamma (χ²)
// and sqrt(2) erfinv(2p - 1) (normal), none of which Boost.Math is.
#include "durability/quantiles.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

TEST_CASE("Student's t upper limits match independently computed quantiles", "[durability][quantiles]") {
    CHECK(student_t_upper_limit(0.99, 56) == Approx(2.39480121939).epsilon(1e-10));
    CHECK(student_t_upper_limit(0.95, 10) == Approx(1.81246112281).epsilon(1e-10));
    CHECK(student_t_upper_limit(0.99, 10) == Approx(2.76376945811).epsilon(1e-10));
    CHECK(student_t_upper_limit(0.975, 3) == Approx(3.18244630528).epsilon(1e-10));
    CHECK(student_t_upper_limit(0.99, 1) == Approx(31.8205159538).epsilon(1e-10));
}

TEST_CASE("chi-squared limits match independently computed quantiles", "[durability][quantiles]") {
    // h1 of {26}: P(H >= h1) = C, i.e. the (1 - C) quantile.
    CHECK(chi_squared_lower_limit(0.99, 56) == Approx(34.3495220572).epsilon(1e-10));
    CHECK(chi_squared_lower_limit(0.95, 10) == Approx(3.94029913612).epsilon(1e-10));
    CHECK(chi_squared_lower_limit(0.99, 10) == Approx(2.55821216019).epsilon(1e-10));
    CHECK(chi_squared_quantile(0.995, 38) == Approx(64.1814123574).epsilon(1e-10));
    CHECK(chi_squared_quantile(0.005, 38) == Approx(19.2889115589).epsilon(1e-10));
}

TEST_CASE("normal quantiles match independently computed values and Table 3's lambda", "[durability][quantiles]") {
    CHECK(normal_quantile(1e-2) == Approx(-2.32634787404).epsilon(1e-10));
    CHECK(normal_quantile(1e-3) == Approx(-3.09023230617).epsilon(1e-10));
    CHECK(normal_quantile(1e-4) == Approx(-3.71901648546).epsilon(1e-10));
    CHECK(normal_quantile(1e-5) == Approx(-4.26489079392).epsilon(1e-10));
    CHECK(normal_quantile(1e-6) == Approx(-4.75342430882).epsilon(1e-10));
    CHECK(normal_quantile(0.5) == Approx(0).margin(1e-15));
}
