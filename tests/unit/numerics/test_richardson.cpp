// Richardson extrapolation with an observed order (numerics/richardson.hpp)
// on synthetic sequences f(h) = f0 + C h^p whose f0 and p are known.
#include "numerics/richardson.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace coremodal;

namespace {

std::vector<double> synthetic(const std::vector<double>& h, double f0, double c, double p) {
    std::vector<double> f;
    for (double x : h) f.push_back(f0 + c * std::pow(x, p));
    return f;
}

}  // namespace

TEST_CASE("Richardson on f(h) = f0 + C h^p recovers f0 and p exactly", "[converge][numerics]") {
    const std::vector<std::vector<double>> ladders = {{1.0 / 2, 1.0 / 3, 1.0 / 4}, {1, 0.5, 0.25}, {0.3, 0.2, 0.11}};
    for (const auto& h : ladders)
        for (double p : {1.0, 2.0, 4.0, 5.5})
            for (double c : {250.0, -40.0}) {
                const auto f = synthetic(h, 133.36, c, p);
                const Richardson r = richardson_three(h.data(), f.data());
                INFO("p = " << p << ", C = " << c << ", h1 = " << h[0]);
                REQUIRE(r.extrapolated);
                CHECK(r.order == Approx(p).epsilon(1e-8));
                CHECK(r.f0 == Approx(133.36).epsilon(1e-11));
                CHECK(r.error_estimate == Approx(std::abs(c) * std::pow(h[2], p)).epsilon(1e-6));
                CHECK(r.asymptotic);
            }
}

TEST_CASE("The observed order solves the ratio of successive changes, capped far beyond plausible orders",
          "[converge][numerics]") {
    const double h[3] = {0.5, 1.0 / 3, 0.25};
    for (double p : {0.7, 2.0, 4.0, 9.0}) {
        // (f1 - f2)/(f2 - f3) of f = C h^p, for any C.
        const double ratio = (std::pow(h[0], p) - std::pow(h[1], p)) / (std::pow(h[1], p) - std::pow(h[2], p));
        CHECK(observed_order(h, ratio) == Approx(p).epsilon(1e-10));
    }
    CHECK(observed_order(h, 1e30) == kMaxSearchedOrder);
}

TEST_CASE("With four levels the order is cross-checked against the coarser triple", "[converge][numerics]") {
    const std::vector<double> h = {1, 0.5, 1.0 / 3, 0.25};
    SECTION("An exact power law is asymptotic and f0 is known to round-off") {
        const Richardson r = richardson(h, synthetic(h, 32.1, 0.9, 4));
        CHECK(r.asymptotic);
        REQUIRE(r.previous_order);
        CHECK(*r.previous_order == Approx(4).epsilon(1e-8));
        REQUIRE(r.f0_uncertainty);
        CHECK(*r.f0_uncertainty < 1e-10);
    }
    SECTION("Two error terms of different order make the triples disagree: not asymptotic") {
        std::vector<double> f;
        for (double x : h) f.push_back(100 + std::pow(x, 4) + 0.5 * x);  // orders ~2.9 and ~1.8
        const Richardson r = richardson(h, f);
        CHECK_FALSE(r.asymptotic);
        CHECK_THAT(r.note, Catch::Contains("not yet asymptotic"));
    }
}

TEST_CASE("Sequences Richardson cannot extrapolate say so and still bound the error", "[converge][numerics]") {
    const double h[3] = {0.5, 1.0 / 3, 0.25};
    SECTION("Alternating changes: no order, the largest change as the error estimate") {
        const double f[3] = {10.0, 10.5, 10.2};
        const Richardson r = richardson_three(h, f);
        CHECK_FALSE(r.extrapolated);
        CHECK_FALSE(r.asymptotic);
        CHECK(r.f0 == 10.2);
        CHECK(r.error_estimate == Approx(0.5));
        CHECK_THAT(r.note, Catch::Contains("not monotone"));
    }
    SECTION("Changes that grow as h shrinks: order <= 0, not asymptotic") {
        const double f[3] = {10.0, 10.1, 10.3};
        const Richardson r = richardson_three(h, f);
        CHECK_FALSE(r.extrapolated);
        CHECK_FALSE(r.asymptotic);
        CHECK(r.error_estimate > 0.2);
        CHECK_THAT(r.note, Catch::Contains("not in the asymptotic range"));
    }
    SECTION("A mode that no longer changes has converged to solver precision") {
        const double f[3] = {466.25, 466.25, 466.25};
        const Richardson r = richardson_three(h, f);
        CHECK(r.asymptotic);
        CHECK(r.f0 == 466.25);
        CHECK(r.error_estimate <= 1e-9 * 466.25 * 1.0001);
        CHECK_THAT(r.note, Catch::Contains("solver precision"));
    }
    SECTION("A first-order rate (a singular clamp edge) is plausible; order 12 is not") {
        const std::vector<double> hh = {0.5, 1.0 / 3, 0.25};
        const auto slow = synthetic(hh, 61.3, 1.5, 1.0);
        CHECK(richardson_three(hh.data(), slow.data()).asymptotic);
        const auto fast = synthetic(hh, 61.3, 1.5, 12.0);
        const Richardson r = richardson_three(hh.data(), fast.data());
        CHECK(r.order == Approx(12).epsilon(1e-6));
        CHECK_FALSE(r.asymptotic);
        CHECK_THAT(r.note, Catch::Contains("outside"));
    }
}
