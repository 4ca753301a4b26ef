// Jorkama's nip against a hand calculation with the paper's example values
// (Jorkama & von Hertzen eq. (5), Fig. 4): drum d1 = 0.85 m, roll radial modulus E = 9.8 MPa,
// nu = 0.3, line load P = 5 kN/m, roll diameters d = 0.4, 1.2, 1.8 m.
#include "winder/nip.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using namespace coremodal;

namespace {

NipInput example(double d, double P) { return {P, d, 0.85, 9.8e6, 0.3}; }

}  // namespace

TEST_CASE("Jorkama's nip matches the hand calculation at the paper's example values", "[winder][nip]") {
    // Common to all three diameters:
    //   E* = 9.8e6 / (1 - 0.09) = 9.8e6 / 0.91 = 1.076923e7 Pa
    //   pi E* = 3.383254e7;  P (1 - nu^2) / (pi E) = 5000 * 0.91 / 3.078761e7 = 1.477867e-4 m
    //   pi E = 3.078761e7 Pa
    // The numbers below were worked with a pocket calculator (6 digits), not with the code.
    struct Row {
        double d, a, delta, k;
    };
    // d = 0.4:  1/d + 1/d1 = 2.5 + 1.176471 = 3.676471 -> d* = 0.272000 m
    //           a^2 = 2 * 0.272 * 5000 / 3.383254e7 = 2720 / 3.383254e7 = 8.039598e-5 -> a = 8.966381e-3 m
    //           2d/a = 0.8 / 8.966381e-3 = 89.2222 -> ln = 4.491130
    //           delta = 1.477867e-4 * (2 * 4.491130 - 1) = 1.477867e-4 * 7.982259 = 1.179672e-3 m
    //           k = 3.078761e7 / (2 * 0.91 * 3.491130) = 3.078761e7 / 6.353856 = 4.845500e6 N/m^2
    // d = 1.2:  1/d + 1/d1 = 0.833333 + 1.176471 = 2.009804 -> d* = 0.497561 m
    //           a^2 = 4975.61 / 3.383254e7 = 1.470658e-4 -> a = 1.212707e-2 m
    //           2d/a = 2.4 / 1.212707e-2 = 197.904 -> ln = 5.287784
    //           delta = 1.477867e-4 * 9.575568 = 1.415142e-3 m
    //           k = 3.078761e7 / (1.82 * 4.287784) = 3.078761e7 / 7.803767 = 3.945224e6 N/m^2
    // d = 1.8:  1/d + 1/d1 = 0.555556 + 1.176471 = 1.732026 -> d* = 0.577358 m
    //           a^2 = 5773.58 / 3.383254e7 = 1.706519e-4 -> a = 1.306338e-2 m
    //           2d/a = 3.6 / 1.306338e-2 = 275.580 -> ln = 5.618876
    //           delta = 1.477867e-4 * 10.237753 = 1.513004e-3 m
    //           k = 3.078761e7 / (1.82 * 4.618876) = 3.078761e7 / 8.406355 = 3.662421e6 N/m^2
    const Row rows[] = {{0.4, 8.966381e-3, 1.179672e-3, 4.845500e6},
                        {1.2, 1.212707e-2, 1.415142e-3, 3.945224e6},
                        {1.8, 1.306338e-2, 1.513004e-3, 3.662421e6}};
    // 6 hand digits: agreement to a few parts in 1e6.
    constexpr double kHandDigits = 5e-6;
    for (const Row& r : rows) {
        CAPTURE(r.d);
        const Nip nip = jorkama_nip(example(r.d, 5000.0));
        CHECK(nip.half_width == Approx(r.a).epsilon(kHandDigits));
        CHECK(nip.deflection == Approx(r.delta).epsilon(kHandDigits));
        CHECK(nip.stiffness_per_length == Approx(r.k).epsilon(kHandDigits));
    }
}

TEST_CASE("The nip stiffness is the derivative of the deflection with respect to the load", "[winder][nip]") {
    // A central difference of delta(P): independent of the closed form of k.
    for (double d : {0.4, 1.2, 1.8})
        for (double P : {1000.0, 5000.0, 20000.0}) {
            CAPTURE(d, P);
            const double h = 1e-4 * P;
            const double slope =
                (jorkama_nip(example(d, P + h)).deflection - jorkama_nip(example(d, P - h)).deflection) / (2 * h);
            // The difference's truncation error is O(h^2 delta''') ~ 1e-8 relative.
            CHECK(jorkama_nip(example(d, P)).stiffness_per_length == Approx(1.0 / slope).epsilon(1e-6));
        }
}

TEST_CASE("The nip gets stiffer as the roll gets smaller and as the load rises", "[winder][nip]") {
    const double k04 = jorkama_nip(example(0.4, 5000)).stiffness_per_length;
    const double k12 = jorkama_nip(example(1.2, 5000)).stiffness_per_length;
    const double k18 = jorkama_nip(example(1.8, 5000)).stiffness_per_length;
    CHECK(k04 > k12);
    CHECK(k12 > k18);
    CHECK(jorkama_nip(example(1.2, 20000)).stiffness_per_length > k12);
}

TEST_CASE("A zero line load opens the nip; a load too high for the formula is refused", "[winder][nip]") {
    const Nip open = jorkama_nip(example(1.2, 0.0));
    CHECK(open.stiffness_per_length == 0.0);
    CHECK(open.half_width == 0.0);
    // ln(2d/a) <= 1 needs a >= 2d/e: for d = 0.1 m on d1 = 0.85 m that is a line
    // load of order 1e7 N/m.
    CHECK_THROWS_AS(jorkama_nip(example(0.1, 1e8)), std::invalid_argument);
    CHECK_THROWS_AS(jorkama_nip({5000, -1.0, 0.85, 9.8e6, 0.3}), std::invalid_argument);
}
