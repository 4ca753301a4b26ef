// The theta integrals of the coupled-harmonic level against a brute-force
// quadrature, and the selection rules they imply (docs/theory/coupled.md,
// "Coupled harmonics").
#include "models/coupled/pad_integrals.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

// The trig factor of component c, written out once more independently of
// pad_integrals.cpp (element/harmonic_element.hpp's fields).
double factor(HarmonicFamily h, int c, double theta) {
    if (h.n == 0) return c == 1 ? -1.0 : 1.0;
    const double a = h.n * theta;
    if (h.family == Family::cos) return c == 1 ? -std::sin(a) : std::cos(a);
    return c == 1 ? std::cos(a) : std::sin(a);
}

// Composite midpoint rule on each arc: second order, 1e-10 at this count.
double brute_force(const std::vector<Arc>& arcs, HarmonicFamily a, HarmonicFamily b, int c) {
    constexpr int kPoints = 20000;
    double sum = 0;
    for (const Arc& arc : arcs) {
        const double h = (arc.to - arc.from) / kPoints;
        for (int i = 0; i < kPoints; ++i) {
            const double t = arc.from + (i + 0.5) * h;
            sum += h * factor(a, c, t) * factor(b, c, t);
        }
    }
    return sum;
}

std::vector<HarmonicFamily> harmonics_up_to(int n_max) {
    std::vector<HarmonicFamily> out{{0, Family::cos}};
    for (int n = 1; n <= n_max; ++n) {
        out.push_back({n, Family::cos});
        out.push_back({n, Family::sin});
    }
    return out;
}

}  // namespace

TEST_CASE("Pad integrals equal a brute-force theta quadrature for every pair of harmonics", "[coupled]") {
    ExpandingElement three{0.07, 0.06, 3, 60 * M_PI / 180};
    ExpandingElement four{0.07, 0.06, 4, 50 * M_PI / 180};
    for (const ExpandingElement& e : {three, four}) {
        const std::vector<Arc> arcs = contact_arcs(e);
        for (HarmonicFamily a : harmonics_up_to(9))
            for (HarmonicFamily b : harmonics_up_to(9))
                for (int c = 0; c < 3; ++c) {
                    INFO("N_s " << e.segments << ", (" << a.n << ", " << int(a.family) << ") x (" << b.n << ", "
                                << int(b.family) << "), component " << c);
                    CHECK(pad_integral(arcs, a, b, c) == Approx(brute_force(arcs, a, b, c)).margin(1e-8));
                }
    }
}

TEST_CASE("Evenly spaced pads couple n only to n +- j N_s, and never a cos family to a sin family", "[coupled]") {
    const ExpandingElement e{0.07, 0.06, 3, 60 * M_PI / 180};
    const std::vector<Arc> arcs = contact_arcs(e);
    for (HarmonicFamily a : harmonics_up_to(10))
        for (HarmonicFamily b : harmonics_up_to(10))
            for (int c = 0; c < 3; ++c) {
                const double v = pad_integral(arcs, a, b, c);
                const bool reachable = (a.n - b.n) % 3 == 0 || (a.n + b.n) % 3 == 0;
                // n = 0's torsion (u_theta) is mirror-odd: it belongs with the sin families.
                const bool a_odd = a.family == Family::sin || (a.n == 0 && c == 1);
                const bool b_odd = b.family == Family::sin || (b.n == 0 && c == 1);
                INFO("(" << a.n << ", " << int(a.family) << ") x (" << b.n << ", " << int(b.family) << "), c " << c);
                if (!reachable || a_odd != b_odd) CHECK(v == 0.0);
            }
    // Closed forms with C(p) = int_pads cos p theta = N_s (2 / p) sin(p alpha / 2) (p a multiple of
    // N_s, else 0; C(0) = N_s alpha = pi): C(3) = 2 sin(pi / 2) = 2, C(6) = sin(pi) = 0.
    CHECK(pad_integral(arcs, {0, Family::cos}, {0, Family::cos}, 0) == Approx(M_PI));
    CHECK(pad_integral(arcs, {1, Family::cos}, {1, Family::cos}, 0) == Approx(M_PI / 2));
    CHECK(pad_integral(arcs, {0, Family::cos}, {3, Family::cos}, 0) == Approx(2.0));  // C(3)
    CHECK(pad_integral(arcs, {1, Family::cos}, {2, Family::cos}, 0) == Approx(1.0));  // (C(-1) + C(3)) / 2
    CHECK(pad_integral(arcs, {1, Family::sin}, {2, Family::sin}, 0) == Approx(-1.0)); // (C(-1) - C(3)) / 2
    CHECK(pad_integral(arcs, {0, Family::cos}, {3, Family::sin}, 1) == Approx(-2.0)); // torsion with sin 3
}

TEST_CASE("A full band gives the harmonic level's weights and no coupling", "[coupled]") {
    const std::vector<Arc> band = contact_arcs(ExpandingElement{0.07, 0.06, 0, 0});
    for (HarmonicFamily a : harmonics_up_to(6))
        for (HarmonicFamily b : harmonics_up_to(6))
            for (int c = 0; c < 3; ++c)
                CHECK(pad_integral(band, a, b, c) == Approx(a == b ? (a.n == 0 ? 2 * M_PI : M_PI) : 0.0).margin(1e-12));
}
