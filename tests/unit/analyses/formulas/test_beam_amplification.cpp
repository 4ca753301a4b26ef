// `coremodal beam --web-speed V [--zeta Z]`: the single-mode amplification
// d(r) of I-2...4 at a web speed, r = f_rot / f1, f_rot = v / (pi Dp).
#include "analyses/formulas/beam_formulas.hpp"
#include "common/error.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

BeamFormulaInputs roll() {
    BeamFormulaInputs in;
    in.di = 0.076, in.do_ = 0.106, in.lc = 2.211, in.dp = 0.2;
    return in;
}

}  // namespace

TEST_CASE("coremodal beam gives the single-mode amplification at a web speed (I-2...4)", "[response][formulas]") {
    const double f1 = beam_formulas(roll()).f1;
    const double dp = 0.2;
    BeamFormulaInputs in = roll();
    in.web_speed = M_PI * dp * f1;  // at resonance: d = 1 / (2 zeta)
    in.zeta = 0.02;
    const BeamFormulas at_resonance = beam_formulas(in);
    REQUIRE(at_resonance.amplification);
    CHECK(at_resonance.amplification->ratio == Approx(1.0).epsilon(1e-12));
    CHECK(at_resonance.amplification->d == Approx(25.0).epsilon(1e-12));
    // Half the speed: r = 0.5, d = 1 / sqrt(0.75^2 + 0.02^2); zeta 0.01 assumed when not given.
    in.web_speed = 0.5 * M_PI * dp * f1;
    in.zeta.reset();
    const BeamFormulas half = beam_formulas(in);
    CHECK(half.amplification->zeta_assumed);
    CHECK(half.amplification->d == Approx(1 / std::sqrt(0.75 * 0.75 + 0.01 * 0.01)).epsilon(1e-12));
    in.web_speed.reset();
    in.zeta = 0.01;
    CHECK_THROWS_AS(beam_formulas(in), InputError);  // --zeta alone: no speed to say it at
}
