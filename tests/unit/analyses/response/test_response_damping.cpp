// [damping] beyond one ratio in the forced response (analyses/response),
// against independent truth: Rayleigh's modal ratios from the closed form
// alpha/(2 omega) + beta omega/2 and from Phi^T (alpha M + beta K) Phi built
// here; the superposition with Rayleigh damping against a direct solve with
// the matrix alpha M + beta K built here; a family's or a mode's own ratio
// moves only the peaks it damps, as 1/zeta at resonance.
#include "models/response/lateral_response.hpp"
#include "analyses/response/response.hpp"
#include "models/response/response_damping.hpp"
#include "models/response/response_loads.hpp"
#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "effects/damping.hpp"
#include "scene/case_file.hpp"
#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <string>

using namespace coremodal;
using cd = std::complex<double>;

namespace {

// The forced-response tests' small clamped rest roll (support/tiny_case.hpp).
Scene clamped_roll() {
    return parse_case_text(testing::kClampedRestRoll, "roll.toml");
}

ResponseSetup bowed(DampingSpec damping, double v0, double v1, int points) {
    ResponseSetup s;
    s.damping = std::move(damping);
    s.excitation.bow_m = 0.5e-3;
    s.excitation.gravity = false;
    for (int i = 0; i < points; ++i) s.response.speeds_hz.push_back((v0 + (v1 - v0) * i / (points - 1)) / (M_PI * 0.196));
    s.response.from_web_speed = true;
    s.response.limit_m = kDefaultAmplitudeLimit;
    s.response.probes = {{"mid-span", 2.0}};
    return s;
}

DampingSpec ratio(double zeta) {
    DampingSpec d;
    d.ratio = zeta;
    d.source = "test";
    return d;
}

// The first elastic bending mode's number among the modes at rest (1-based).
int first_bending(const BeamModelResult& rest) {
    for (size_t k = 0; k < rest.modes.size(); ++k)
        if (rest.modes[k].label.type == "bending") return static_cast<int>(k) + 1;
    return 0;
}

}  // namespace

TEST_CASE("Rayleigh damping gives mode j the ratio alpha / (2 omega_j) + beta omega_j / 2", "[response][analyses]") {
    const BeamModelResult rest = solve_beam_model(clamped_roll());
    LateralResponse lateral(rest.network, rest.lambda_scale);
    const double w1 = 2 * M_PI * rest.modes.front().frequency_hz;
    const RayleighDamping rayleigh = RayleighDamping::at_two_frequencies(0.01, w1, 5 * w1);
    lateral.set_damping(rayleigh, std::vector<std::optional<double>>(static_cast<size_t>(lateral.n_modes())));
    const Eigen::MatrixXd K(lateral.matrices().K), M(lateral.matrices().M);
    const Eigen::MatrixXd D = rayleigh.alpha * M + rayleigh.beta * K;
    for (int j = 0; j < 12; ++j) {
        const double w = 2 * M_PI * lateral.mode_frequency_hz(j);
        const Eigen::VectorXd phi = lateral.to_rows(lateral.mode_shape(j).cast<cd>()).real();
        // The closed form, and phi^T D phi / (2 omega) with D built here; 1e-10:
        // M-orthonormality of the dense eigenvectors (~1e-13) times the spread of alpha M and beta K.
        CHECK(lateral.modal_damping_ratio(j) == Approx(rayleigh.alpha / (2 * w) + rayleigh.beta * w / 2).epsilon(1e-10));
        CHECK(lateral.modal_damping_ratio(j) == Approx(phi.dot(D * phi) / (2 * w)).epsilon(1e-10));
    }
    // zeta = 0.01 at the first mode itself.
    CHECK(lateral.modal_damping_ratio(0) == Approx(0.01).epsilon(1e-10));
}

TEST_CASE("Superposition with Rayleigh damping is the direct solve with D = alpha M + beta K", "[response][analyses]") {
    const Scene scene = clamped_roll();
    const BeamModelResult rest = solve_beam_model(scene);
    LateralResponse lateral(rest.network, rest.lambda_scale);
    const double f1 = rest.modes.front().frequency_hz;
    const RayleighDamping rayleigh = RayleighDamping::at_two_frequencies(0.01, 2 * M_PI * f1, 2 * M_PI * 4 * f1);
    lateral.set_damping(rayleigh, std::vector<std::optional<double>>(static_cast<size_t>(lateral.n_modes())));
    ExcitationSpec x;
    x.bow_m = 0.5e-3;
    x.ovality_m = 0.3e-3;
    const ResponseLoads loads = build_response_loads(scene, x, rest.network, lateral, {});
    const Eigen::MatrixXd K(lateral.matrices().K), M(lateral.matrices().M);
    const Eigen::MatrixXd D = rayleigh.alpha * M + rayleigh.beta * K;
    for (const OrderLoad& load : loads.orders)
        for (const double share : {0.2, 0.97, 1.0, 1.6, 3.0}) {  // below, near, at and above the first bending mode
            const double spin = 2 * M_PI * share * f1 / load.order, omega = load.order * spin;
            const Eigen::VectorXcd f = lateral.to_rows(load.at(spin));
            // Without the spin's gyroscopic term, against the LU of the full
            // system assembled here: K - w^2 M + i w (alpha M + beta K).
            const Eigen::MatrixXcd A = (K - omega * omega * M).cast<cd>() + cd(0, omega) * D.cast<cd>();
            const Eigen::VectorXcd here = A.partialPivLu().solve(f);
            const Eigen::VectorXcd still = lateral.superpose(f, 0, omega, lateral.n_modes());
            // 1e-6 is the bound; one linear system in two bases agrees
            // to round-off times its condition (~1e-10).
            CHECK((still - here).norm() / here.norm() < 1e-6);
            // Spinning, with G: the complete basis against LateralResponse::direct.
            const Eigen::VectorXcd modal = lateral.superpose(f, spin, omega, lateral.n_modes());
            const Eigen::VectorXcd direct = lateral.direct(f, spin, omega);
            CHECK((modal - direct).norm() / direct.norm() < 1e-6);
        }
}

TEST_CASE("A Rayleigh run: each kept mode's zeta from the closed form, checked against the direct solve",
          "[response][analyses]") {
    const Scene scene = clamped_roll();
    DampingSpec d;
    d.rayleigh = RayleighSpec{0.8, 2e-5};
    d.source = "test rayleigh";
    const ResponseResult r = run_forced_response(scene, bowed(d, 5, 40, 60));
    CHECK(r.checks.direct_max_relative < 1e-6);
    REQUIRE(r.mode_damping.size() == static_cast<size_t>(r.checks.n_modes_used));
    for (const ModeDamping& m : r.mode_damping) {
        const double w = 2 * M_PI * m.frequency_hz;
        CHECK(m.zeta == Approx(0.8 / (2 * w) + 2e-5 * w / 2).epsilon(1e-12));
        CHECK(m.from == "rayleigh");
    }
    CHECK(std::find(r.effects.begin(), r.effects.end(), "rayleigh_damping") != r.effects.end());
    CHECK(std::find(r.effects.begin(), r.effects.end(), "modal_damping") == r.effects.end());
}

TEST_CASE("A family's ratio moves only that family's peak, as 1 / zeta", "[long][response][analyses]") {
    const Scene scene = clamped_roll();
    const ResponseResult base = run_forced_response(scene, bowed(ratio(0.01), 5, 40, 60));
    // Every lateral mode at the beam level is a bending mode: bending = 0.02
    // halves the order-1 peak (the off-resonant modes answer in quadrature:
    // O(zeta^2), the 1e-3 of test_response.cpp).
    DampingSpec bending = ratio(0.01);
    bending.families.push_back({"bending", 0.02});
    const ResponseResult halved = run_forced_response(scene, bowed(bending, 5, 40, 60));
    REQUIRE(base.peaks.size() == 1);
    REQUIRE(halved.peaks.size() == 1);
    CHECK(base.peaks[0].amplitude_m / halved.peaks[0].amplitude_m == Approx(2.0).epsilon(1e-3));
    for (const ModeDamping& m : halved.mode_damping) CHECK(m.from == "bending");
    // A torsion ratio damps no mode of the lateral response: bit for bit the same, and said so.
    DampingSpec torsion = ratio(0.01);
    torsion.families.push_back({"torsion", 0.05});
    const ResponseResult same = run_forced_response(scene, bowed(torsion, 5, 40, 60));
    for (size_t i = 0; i < base.points.size(); ++i) CHECK(same.points[i].probes[0].total_m == base.points[i].probes[0].total_m);
    CHECK(std::find(same.assumptions.begin(), same.assumptions.end(),
                    "[damping] torsion = 0.05: no torsion mode in the lateral response (bending only): it damps "
                    "nothing here") != same.assumptions.end());
}

TEST_CASE("A mode's own ratio damps it and its degenerate partner, and no other peak", "[long][response][analyses]") {
    const Scene scene = clamped_roll();
    const BeamModelResult rest = solve_beam_model(scene);
    const int first = first_bending(rest);
    REQUIRE(first > 0);
    // The first bending mode is a pair (both planes): naming either damps the whirl.
    REQUIRE(rest.modes[static_cast<size_t>(first)].frequency_hz == Approx(rest.modes[first - 1].frequency_hz).epsilon(1e-9));
    const ResponseResult base = run_forced_response(scene, bowed(ratio(0.01), 5, 40, 60));
    for (const int named : {first, first + 1}) {
        DampingSpec own = ratio(0.01);
        own.modes.push_back({named, 0.02, "roll.toml:20:9: [damping.modes #1]"});
        const ResponseResult r = run_forced_response(scene, bowed(own, 5, 40, 60));
        REQUIRE(r.peaks.size() == 1);
        CHECK(base.peaks[0].amplitude_m / r.peaks[0].amplitude_m == Approx(2.0).epsilon(1e-3));
        REQUIRE(r.mode_damping.size() >= 3);
        CHECK(r.mode_damping[0].rest_modes == std::vector<int>{first, first + 1});
        CHECK(r.mode_damping[0].zeta == 0.02);
        CHECK(r.mode_damping[1].zeta == 0.02);
        CHECK(r.mode_damping[2].zeta == 0.01);  // the second bending pair keeps the base
    }
    // The next symmetric bending pair (m = 2; m = 1 has a node at mid-span,
    // where the probe is) answers the bow too, off resonance: five times its
    // damping moves the first peak only by its quadrature share, O(zeta^2):
    // measured 2.7e-7, bound 1e-5, far below the factor 2 above.
    int symmetric = 0;
    for (size_t k = 0; k < rest.modes.size() && !symmetric; ++k)
        if (rest.modes[k].label.type == "bending" && rest.modes[k].label.m == 2) symmetric = static_cast<int>(k) + 1;
    REQUIRE(symmetric > 0);
    DampingSpec other = ratio(0.01);
    other.modes.push_back({symmetric, 0.05, "roll.toml:20:9: [damping.modes #1]"});
    const ResponseResult r = run_forced_response(scene, bowed(other, 5, 40, 60));
    CHECK(r.peaks[0].amplitude_m != base.peaks[0].amplitude_m);  // it does answer
    CHECK(r.peaks[0].amplitude_m == Approx(base.peaks[0].amplitude_m).epsilon(1e-5));
}

TEST_CASE("Mode numbers are checked against the modes at rest", "[response][analyses]") {
    const Scene scene = clamped_roll();
    const BeamModelResult rest = solve_beam_model(scene);
    const int first = first_bending(rest);
    DampingSpec beyond = ratio(0.01);
    beyond.modes.push_back({99, 0.02, "roll.toml:20:9: [damping.modes #1]"});
    // [analysis] modes = 8 computes 9: the solver completes the last degenerate pair.
    const std::string n = std::to_string(rest.modes.size());
    CHECK_THROWS_WITH(run_forced_response(scene, bowed(beyond, 5, 40, 10)),
                      "roll.toml:20:9: [damping.modes #1] mode = 99 is not among the " + n +
                          " modes at rest the run computes; expected a mode from 1 to " + n +
                          " (as in modes.csv), or more [analysis] modes");
    DampingSpec pair = ratio(0.01);
    pair.modes.push_back({first, 0.02, "roll.toml:20:9: [damping.modes #1]"});
    pair.modes.push_back({first + 1, 0.03, "roll.toml:20:30: [damping.modes #2]"});
    CHECK_THROWS_WITH(run_forced_response(scene, bowed(pair, 5, 40, 10)),
                      Catch::Contains("roll.toml:20:30: [damping.modes #2] mode = " + std::to_string(first + 1)) &&
                          Catch::Contains("are one degenerate pair (bending n=1 m=0"));
    // A torsion or axial mode's number is accepted and said to damp nothing here.
    int twisting = 0;
    for (size_t k = 0; k < rest.modes.size() && !twisting; ++k)
        if (rest.modes[k].label.type == "torsion" || rest.modes[k].label.type == "axial") twisting = static_cast<int>(k) + 1;
    REQUIRE(twisting > 0);
    DampingSpec axial = ratio(0.01);
    axial.modes.push_back({twisting, 0.02, "roll.toml:20:9: [damping.modes #1]"});
    const ResponseResult r = run_forced_response(scene, bowed(axial, 5, 40, 10));
    const std::string note = "[damping] mode " + std::to_string(twisting) + " (";
    CHECK(std::count_if(r.assumptions.begin(), r.assumptions.end(), [&](const std::string& a) {
              return a.starts_with(note) && a.ends_with("is not in the lateral response (bending only): its ratio 0.02 "
                                                        "damps nothing here");
          }) == 1);
}
