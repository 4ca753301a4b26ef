// The axisymmetric equivalent of segmented chucks (models/coupled/
// axisymmetric_equivalent.hpp): its band's n = 1 stiffness equals the pads',
// against a hand calculation, and the chucks it cannot carry are refused.
#include "models/coupled/axisymmetric_equivalent.hpp"

#include "common/error.hpp"
#include "models/coupled/pad_integrals.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace coremodal;

namespace {

constexpr double kPi = std::numbers::pi;

// A scene with one chuck at each end, each with one element of `segments`
// pads of `angle` rad on a spring layer (only what the equivalent reads).
Scene chucked(int segments, double angle) {
    Scene s;
    s.source_file = "pads.toml";
    s.supports.kind = SupportKind::chucks;
    for (const char* name : {"left", "right"}) {
        ChuckSpec c;
        c.name = name;
        c.expanding = {{0.05, 0.04, segments, angle}};
        c.interface.kind = InterfaceKind::spring;
        c.interface.normal_stiffness = 2e12;
        c.interface.tangential_stiffness = 5e11;
        s.supports.chucks.push_back(c);
    }
    return s;
}

}  // namespace

TEST_CASE("the equivalent band's n = 1 stiffness equals three 60-degree pads'", "[coupled][limits]") {
    const Scene pads = chucked(3, kPi / 3);
    const AxisymmetricEquivalent eq = axisymmetric_equivalent(pads);
    // By hand: 3 x 60 deg = 180 deg of 360: coverage 0.5.
    CHECK(eq.coverage == Approx(0.5).epsilon(1e-14));
    const ChuckSpec& band = eq.scene.supports.chucks.front();
    CHECK(band.expanding.front().segments == 0);
    CHECK(band.interface.normal_stiffness == Approx(1e12).epsilon(1e-14));
    CHECK(band.interface.tangential_stiffness == Approx(2.5e11).epsilon(1e-14));
    // The layer's n = 1 stiffness per unit length and bore radius is
    // k_c int chi t_c t_c dtheta: over the pads, by hand,
    // sum_k int cos^2 = N alpha / 2 + sin(alpha) / 2 sum_k cos(2 theta_k) = pi / 2 (the sum is 0 for N = 3);
    // over the full band, pi.
    const std::vector<Arc> arcs = contact_arcs(pads.supports.chucks.front().expanding.front());
    const std::vector<Arc> full{{0, 2 * kPi}};
    const double k[3] = {2e12, 5e11, 5e11};  // r: normal; theta, z: tangential
    const double k_eq[3] = {band.interface.normal_stiffness, band.interface.tangential_stiffness,
                            band.interface.tangential_stiffness};
    for (Family f : {Family::cos, Family::sin}) {
        const HarmonicFamily h{1, f};
        for (int c = 0; c < 3; ++c) {
            CHECK(pad_integral(arcs, h, h, c) == Approx(kPi / 2).epsilon(1e-12));
            CHECK(k_eq[c] * pad_integral(full, h, h, c) == Approx(k[c] * pad_integral(arcs, h, h, c)).epsilon(1e-12));
        }
    }
    // No cos-sin coupling within n = 1 (a band has none either).
    CHECK(std::abs(pad_integral(arcs, {1, Family::cos}, {1, Family::sin}, 0)) < 1e-12);
    CHECK(eq.assumption.find("coverage 50 %") != std::string::npos);
}

TEST_CASE("two pads have no axisymmetric equivalent: refused with the reason", "[coupled][limits]") {
    // Two pads: sum_k cos^2 over them is N alpha/2 + sin(alpha)/2 x 2, stiffer in x than in y.
    const std::vector<Arc> arcs = contact_arcs({0.05, 0.04, 2, kPi / 3});
    CHECK(pad_integral(arcs, {1, Family::cos}, {1, Family::cos}, 0) ==
          Approx(kPi / 3 + std::sin(kPi / 3)).epsilon(1e-12));
    try {
        axisymmetric_equivalent(chucked(2, kPi / 3));
        FAIL("two pads accepted");
    } catch (const InputError& e) {
        const std::string what = e.what();
        CHECK(what.find("pads.toml") != std::string::npos);
        CHECK(what.find("left chuck") != std::string::npos);
        CHECK(what.find("segments >= 3") != std::string::npos);
    }
}

TEST_CASE("a chuck without pads is kept as it is", "[coupled][limits]") {
    const AxisymmetricEquivalent eq = axisymmetric_equivalent(chucked(0, 0));
    CHECK(eq.coverage == 1.0);
    CHECK(eq.scene.supports.chucks.front().interface.normal_stiffness == 2e12);
    CHECK(eq.assumption.empty());
}
