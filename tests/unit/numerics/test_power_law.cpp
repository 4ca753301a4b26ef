// Power-law fits (numerics/power_law.hpp): the exponent b of y = a x^b,
// exact on exact data, and nothing where no slope is defined.
#include "numerics/power_law.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace coremodal;

TEST_CASE("Power laws of time and memory against DOFs", "[converge][numerics]") {
    const std::vector<double> dofs = {1e4, 3e4, 1e5, 5e5};
    for (double b : {-0.5, 0.0, 1.2, 3.0}) {
        std::vector<double> y;
        for (double n : dofs) y.push_back(2e-4 * std::pow(n, b));
        const auto e = power_law_exponent(dofs, y);
        REQUIRE(e);
        CHECK(*e == Approx(b).margin(1e-12));
    }
    SECTION("Points with a non-positive value are left out") {
        CHECK(*power_law_exponent({0.0, 1e4, 3e4, 1e5}, {5.0, 1e8, 9e8, 1e10}) == Approx(2).epsilon(1e-12));
        CHECK(*power_law_exponent({1e4, 3e4, 1e5}, {1e8, -1.0, 1e10}) == Approx(2).epsilon(1e-12));
    }
    SECTION("Fewer than two points, or one x, give no exponent") {
        CHECK_FALSE(power_law_exponent({1e4}, {2.0}));
        CHECK_FALSE(power_law_exponent({1e4, 1e4}, {2.0, 3.0}));
        CHECK_FALSE(power_law_exponent({}, {}));
    }
}
