// The verdict's shortcuts at the harmonic level (docs/how-to/limits.md,
// "Speed") against the computations they replace, on a small clamped roll at
// the coarse mesh: the run at rest of wave number n = 1 only gives the whole
// run's f1 and response; the band's damping and bow samples on the point's
// own n = 1 model give the re-solved samples' numbers.
#include "analyses/limits/limits.hpp"
#include "analyses/limits/limits_band.hpp"
#include "analyses/response/response.hpp"
#include "scene/limits_spec.hpp"
#include "scene/mesh_levels.hpp"

#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;

namespace {

// Case 12's core clamped over 70 mm with 10 mm of rest paper, a 0.5 mm bow
// and 1 % damping, at the harmonic level's coarse mesh.
LimitsCase small_harmonic_roll() {
    const std::string& text = testing::kBowedTesterRoll;
    LimitsCase c = parse_limits_case_text(text, "small.toml");
    c.scene.model = ModelChoice::harmonic;
    apply_mesh_level(c.scene, "coarse");
    return c;
}

void check_same_response(const ResponseResult& a, const ResponseResult& b, double tolerance) {
    CHECK(a.speeds_at_rest.f1_hz == Approx(b.speeds_at_rest.f1_hz).epsilon(tolerance));
    REQUIRE(a.points.size() == b.points.size());
    for (size_t i = 0; i < a.points.size(); ++i)
        CHECK(a.points[i].probes[0].total_m == Approx(b.points[i].probes[0].total_m).epsilon(tolerance));
    REQUIRE(a.safe.reached == b.safe.reached);
    CHECK(a.safe.web_speed_m_s == Approx(b.safe.web_speed_m_s).epsilon(tolerance));
    REQUIRE(a.peaks.size() == b.peaks.size());
    for (size_t i = 0; i < a.peaks.size(); ++i) {
        CHECK(a.peaks[i].web_speed_m_s == Approx(b.peaks[i].web_speed_m_s).epsilon(tolerance));
        CHECK(a.peaks[i].amplitude_m == Approx(b.peaks[i].amplitude_m).epsilon(tolerance));
    }
}

}  // namespace

TEST_CASE("The harmonic response's run at rest of n = 1 only gives the whole run's f1 and response",
          "[limits][speed]") {
    // RestModes::lateral takes f1 from the response's own n = 1 basis (the
    // same operators and eigensolver as the whole run's n = 1 family) instead
    // of the level's run over every wave number: the same f1, I-5 and response
    // to the eigensolver's tolerance (1e-8 relative on the eigenvalues).
    const LimitsCase c = small_harmonic_roll();
    const ResponseResult every = run_forced_response(c.scene, *c.response, {}, ResponseChecking::none);
    const ResponseResult lateral =
        run_forced_response(c.scene, *c.response, {}, ResponseChecking::none, RestModes::lateral);
    REQUIRE(every.speeds_at_rest.f1_hz > 0);
    check_same_response(lateral, every, 1e-7);
    REQUIRE(lateral.speeds_at_rest.safe.size() == every.speeds_at_rest.safe.size());
    for (size_t i = 0; i < every.speeds_at_rest.safe.size(); ++i)
        CHECK(lateral.speeds_at_rest.safe[i].v_safe_m_s ==
              Approx(every.speeds_at_rest.safe[i].v_safe_m_s).epsilon(1e-7));
}

TEST_CASE("The band's damping and bow samples on the point's own n = 1 model give the re-solved samples",
          "[limits][speed]") {
    // run_forced_responses builds the n = 1 basis, its labels and the factor
    // of K once and sweeps each setup on it; each setup re-solved on its own
    // is the same arithmetic on the same matrices, so the numbers agree to
    // round-off (1e-9 relative).
    const LimitsCase c = small_harmonic_roll();
    ResponseSetup damped = *c.response, bowed = *c.response;
    damped.damping.ratio = 0.03;    // the band's damping sample
    bowed.excitation.bow_m = 1e-3;  // the band's bow sample: twice the case's bow
    const std::vector<ResponseResult> shared =
        run_forced_responses(c.scene, {damped, bowed}, ResponseChecking::none, RestModes::lateral);
    REQUIRE(shared.size() == 2);
    check_same_response(shared[0], run_forced_response(c.scene, damped, {}, ResponseChecking::none, RestModes::lateral),
                        1e-9);
    check_same_response(shared[1], run_forced_response(c.scene, bowed, {}, ResponseChecking::none, RestModes::lateral),
                        1e-9);
    // and the samples differ from each other (the test can fail): more
    // damping lowers the resonant peak.
    REQUIRE(!shared[0].peaks.empty());
    CHECK(shared[0].max_amplitude_m < shared[1].max_amplitude_m);
}

TEST_CASE("The band's damping and bow samples on one n = 1 model are the re-solved samples", "[limits][speed]") {
    // run_forced_responses assembles, solves and labels the n = 1 basis and
    // factors K once for setups that change neither K nor M; each result is
    // then the separate run's arithmetic on the same basis: equal to the
    // eigensolver's tolerance. Independent check of the bow's linearity: the
    // orbit at twice the bow is twice the orbit (the load and the runout are
    // linear in the bow; gravity's sag is not counted as vibration).
    const LimitsCase c = small_harmonic_roll();
    std::vector<ResponseSetup> setups(3, *c.response);
    setups[1].damping.ratio = 0.02;
    setups[2].excitation.bow_m *= 2;
    const std::vector<ResponseResult> together =
        run_forced_responses(c.scene, setups, ResponseChecking::none, RestModes::lateral);
    REQUIRE(together.size() == setups.size());
    for (size_t k = 0; k < setups.size(); ++k) {
        INFO("setup " << k);
        check_same_response(
            together[k], run_forced_response(c.scene, setups[k], {}, ResponseChecking::none, RestModes::lateral), 1e-7);
        CHECK(together[k].crossings.size() == together[0].crossings.size());
    }
    // More damping: a lower first peak.
    REQUIRE(!together[0].peaks.empty());
    REQUIRE(!together[1].peaks.empty());
    CHECK(together[1].peaks[0].amplitude_m < together[0].peaks[0].amplitude_m);
    for (size_t i = 0; i < together[0].points.size(); ++i)
        CHECK(together[2].points[i].probes[0].total_m ==
              Approx(2 * together[0].points[i].probes[0].total_m).epsilon(1e-9));
}
