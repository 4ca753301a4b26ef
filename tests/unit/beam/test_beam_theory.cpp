// Beam theory of a core (src/beam/beam_theory.hpp): Cowper's shear
// coefficient, section properties, Euler–Bernoulli, and the Timoshenko
// finite-element model against its limits and against the exact Timoshenko
// frequency equation solved here by bisection.
#include "beam/beam_theory.hpp"

#include "support/timoshenko_exact.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <vector>

using namespace coremodal;
using coremodal::testing::exact_timoshenko_first_hz;

namespace {

constexpr double pi = M_PI;

double ring_area(double d_out, double d_in) { return pi / 4 * (d_out * d_out - d_in * d_in); }
double ring_inertia(double d_out, double d_in) { return pi / 64 * (std::pow(d_out, 4) - std::pow(d_in, 4)); }

// Isotropic steel tube Do 200 mm, Di 100 mm: short and thick over 1 m
// (L / radius of gyration = 1 / 0.0559 = 17.9), where shear and rotary
// inertia matter.
BeamSection steel_tube(double d_out = 0.2, double d_in = 0.1) {
    const double E = 210e9, nu = 0.3, G = E / (2 * (1 + nu)), rho = 7850;
    const double A = ring_area(d_out, d_in), I = ring_inertia(d_out, d_in);
    BeamSection s;
    s.EI = E * I;
    s.rho_A = rho * A;
    s.rho_I = rho * I;
    s.kappa_GA = cowper_hollow_circle(nu, d_in / d_out) * G * A;
    return s;
}

}  // namespace

TEST_CASE("Cowper's shear coefficient of a hollow circle at its known limits", "[beam]") {
    // Cowper (1966), hollow circle m = ri/ro:
    //   kappa = 6 (1 + nu)(1 + m^2)^2 / ((7 + 6 nu)(1 + m^2)^2 + (20 + 12 nu) m^2)
    // Solid circle, m = 0: 6 (1 + nu)/(7 + 6 nu): nu = 0 -> 6/7; nu = 0.3 -> 7.8/8.8.
    CHECK(cowper_hollow_circle(0.0, 0.0) == Approx(6.0 / 7.0).epsilon(1e-14));
    CHECK(cowper_hollow_circle(0.3, 0.0) == Approx(7.8 / 8.8).epsilon(1e-14));
    // Thin-walled tube, m -> 1: 24 (1 + nu)/(4 (7 + 6 nu) + 20 + 12 nu) = 2 (1 + nu)/(4 + 3 nu):
    // nu = 0 -> 0.5; nu = 0.3 -> 2.6/4.9 = 0.530612.
    CHECK(cowper_hollow_circle(0.0, 1.0) == Approx(0.5).epsilon(1e-14));
    CHECK(cowper_hollow_circle(0.3, 1.0) == Approx(2.6 / 4.9).epsilon(1e-14));
    CHECK(cowper_hollow_circle(0.3, 0.999999) == Approx(2.6 / 4.9).epsilon(1e-9));
    // In between, m = 0.5, nu = 0.3: (1 + m^2)^2 = 1.5625;
    // 6 * 1.3 * 1.5625 / (8.8 * 1.5625 + 23.6 * 0.25) = 12.1875 / 19.65 = 0.620229.
    CHECK(cowper_hollow_circle(0.3, 0.5) == Approx(12.1875 / 19.65).epsilon(1e-14));
}

TEST_CASE("Beam section of a core with rest paper, and the span of a scene", "[beam]") {
    Scene scene;
    scene.core.inner_diameter = 0.076, scene.core.outer_diameter = 0.106, scene.core.length = 2.0;
    scene.core.material = OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850);
    RestPaperSpec paper;
    paper.outer_diameter = 0.126;
    paper.material = OrthotropicMaterial::isotropic("paper", 5e9, 0.25, 1350);
    scene.rest_paper = paper;
    const BeamSection s = beam_section(scene);
    // Core: Ac = pi/4 (0.106^2 - 0.076^2) = 4.28827e-3 m^2, Ic = pi/64 (0.106^4 - 0.076^4) = 4.55951e-6 m^4.
    // Paper: Ap = pi/4 (0.126^2 - 0.106^2) = 3.64425e-3 m^2, Ip = pi/64 (0.126^4 - 0.106^4) = 6.17518e-6 m^4.
    const double Ac = 4.28827e-3, Ic = 4.55951e-6, Ap = 3.64425e-3, Ip = 6.17518e-6;
    CHECK(s.EI == Approx(210e9 * Ic + 5e9 * Ip).epsilon(1e-5));  // 9.57497e5 + 3.08759e4 N m^2
    CHECK(s.rho_A == Approx(7850 * Ac + 1350 * Ap).epsilon(1e-5));
    CHECK(s.rho_I == Approx(7850 * Ic + 1350 * Ip).epsilon(1e-5));
    // Shear: kappa G A per layer, G = E / (2 (1 + nu)), Cowper with m = Di/Do of the layer.
    const double kGA = cowper_hollow_circle(0.3, 0.076 / 0.106) * 210e9 / 2.6 * Ac +
                       cowper_hollow_circle(0.25, 0.106 / 0.126) * 5e9 / 2.5 * Ap;
    CHECK(s.kappa_GA == Approx(kGA).epsilon(1e-5));

    CHECK(beam_span(scene) == 2.0);  // free scene: the core length
    scene.core.length = 4.32;
    scene.supports.kind = SupportKind::clamped;
    scene.supports.clamps = {{"left", 0.2, 0.3}, {"right", 4.02, 4.12}};
    CHECK(beam_span(scene) == Approx(3.72).epsilon(1e-14));  // 4.02 - 0.3: between the inner edges
}

TEST_CASE("Euler-Bernoulli first bending frequency by hand", "[beam]") {
    // Steel tube 200 x 100 mm, L = 1 m:
    //   I = pi/64 (0.2^4 - 0.1^4) = 7.36311e-5 m^4, EI = 210e9 I = 1.546253e7 N m^2
    //   A = pi/4 (0.2^2 - 0.1^2) = 2.356194e-2 m^2, rho A = 7850 A = 184.9613 kg/m
    //   f = 4.7300407^2/(2 pi) sqrt(EI/rhoA) = 3.560819 * 289.1344 = 1029.555 Hz
    const BeamSection s = steel_tube();
    CHECK(euler_bernoulli_first_bending_hz(s, 1.0) == Approx(3.560819 * 289.1344).epsilon(1e-6));
    // 1/L^2 scaling: twice as long, a quarter of the frequency.
    CHECK(euler_bernoulli_first_bending_hz(s, 2.0) == Approx(euler_bernoulli_first_bending_hz(s, 1.0) / 4));
}

TEST_CASE("Timoshenko beam tends to Euler-Bernoulli without shear and rotary inertia", "[beam]") {
    BeamSection s = steel_tube();
    const double L = 1.0, f_eb = euler_bernoulli_first_bending_hz(s, L);
    for (BeamEnds ends : {BeamEnds::clamped_clamped, BeamEnds::free_free}) {
        // kGA = t EI/L^2 and rhoI = rhoA L^2/t: both corrections are first order
        // in 1/t, so the gap to Euler–Bernoulli times t tends to a constant
        // (about 30.9 here for both end conditions), and Richardson's
        // extrapolation f + (f(t) - f(t/10))/9 removes it. (rhoI = 0 exactly
        // makes the mass matrix singular; beyond t ~ 1e6 the dense generalized
        // eigensolver's rounding, not the model, dominates the gap.)
        std::vector<double> f, t = {1e4, 1e5, 1e6};
        for (double ti : t) {
            s.kappa_GA = ti * s.EI / (L * L);
            s.rho_I = s.rho_A * L * L / ti;
            f.push_back(timoshenko_bending_hz(s, L, ends, 1).at(0));
        }
        for (size_t i = 0; i < t.size(); ++i) CHECK(f[i] < f_eb);  // shear and rotary inertia only soften
        const double c4 = (1 - f[0] / f_eb) * t[0], c5 = (1 - f[1] / f_eb) * t[1], c6 = (1 - f[2] / f_eb) * t[2];
        CHECK(c5 == Approx(c4).epsilon(0.01));  // gap = c / t: first-order convergence
        CHECK(c6 == Approx(c5).epsilon(0.01));
        CHECK(1 - f[2] / f_eb < 4e-5);
        const double limit = f[2] + (f[2] - f[1]) / 9;
        CHECK(std::abs(limit / f_eb - 1) < 1e-6);
    }
}

TEST_CASE("Short thick tube: Timoshenko model matches the exact frequency equation", "[beam]") {
    const BeamSection s = steel_tube();
    const double L = 1.0, f_eb = euler_bernoulli_first_bending_hz(s, L);  // 1029.56 Hz
    for (BeamEnds ends : {BeamEnds::clamped_clamped, BeamEnds::free_free}) {
        const double exact = exact_timoshenko_first_hz(s, L, ends);
        const double fe = timoshenko_bending_hz(s, L, ends, 1).at(0);
        INFO((ends == BeamEnds::clamped_clamped ? "clamped-clamped" : "free-free")
             << ": EB " << f_eb << " Hz, exact Timoshenko " << exact << " Hz, FE " << fe << " Hz");
        CHECK(fe == Approx(exact).epsilon(1e-6));
        CHECK(exact < f_eb);
    }
    // The drop this thick tube (L/r = 17.9, E/(kappa G) = 2.6/0.620 = 4.19) takes:
    // clamped-clamped 794.893 Hz = 0.7721 f_EB, free-free 903.925 Hz = 0.8780 f_EB
    // (the roots of the equation above; clamped ends, with their steeper end
    // curvature, feel shear more).
    CHECK(exact_timoshenko_first_hz(s, L, BeamEnds::clamped_clamped) / f_eb == Approx(0.7721).epsilon(1e-4));
    CHECK(exact_timoshenko_first_hz(s, L, BeamEnds::free_free) / f_eb == Approx(0.8780).epsilon(1e-4));
}

TEST_CASE("Timoshenko beams shorter than their diameter keep every elastic mode, however short", "[beam]") {
    // The two rigid modes of a free-free beam are counted out, not cut off
    // below a share of the Euler-Bernoulli frequency: that share dropped the
    // shear modes of a short beam, and every mode of a 10 um one (issue 11).
    const BeamSection s = steel_tube();  // 200 x 100 mm
    for (double L : {1.0, 0.2, 0.02, 1e-3, 1e-5}) {
        INFO("L = " << L << " m");
        for (BeamEnds ends : {BeamEnds::clamped_clamped, BeamEnds::free_free}) {
            const std::vector<double> f = timoshenko_bending_hz(s, L, ends, 3);
            REQUIRE(f.size() == 3);
            CHECK(f[0] > 0);
            CHECK(f[0] <= f[1]);
            CHECK(f[1] <= f[2]);
            CHECK(std::isfinite(f[2]));
        }
    }
    // L = 0.4 m = 7.2 radii of gyration, below the shear cut-off: the exact
    // frequency equation's first root, 0.62 f_EB (the old cut at 0.01 f_EB
    // still kept this one; a 10 mm ring had its first mode dropped).
    const double L = 0.4, exact = exact_timoshenko_first_hz(s, L, BeamEnds::free_free, 0.1);
    CHECK(timoshenko_bending_hz(s, L, BeamEnds::free_free, 1).at(0) == Approx(exact).epsilon(1e-6));
    CHECK(exact / euler_bernoulli_first_bending_hz(s, L) == Approx(0.619).epsilon(1e-3));
}
