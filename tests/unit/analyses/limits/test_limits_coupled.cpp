// The verdict at the coupled level (segmented chucks; limits.hpp,
// coupled_verdict): f1 at the coupled level equals `coremodal run --model
// coupled` on the same scene and diameter; the spinning criteria equal the
// harmonic level's verdict on the axisymmetric equivalent; two pads are
// refused with the reason. A coarse news roll, one diameter, no band.
#include "analyses/limits/limits.hpp"

#include "analyses/run/run.hpp"
#include "common/error.hpp"
#include "models/coupled/axisymmetric_equivalent.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

namespace {

// Case 10's chucks (three 60-degree pads at 6 bar) on case 17's news roll,
// 20 mm of rest paper, the coarse mesh.
std::string news_roll(int segments) {
    return R"(name = "segmented-news"
model = "coupled"
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2.2 m"
material = "paperboard_core"
[rest_paper]
thickness = "20 mm"
material = "rest_paper"
[supports]
type = "chucks"
[supports.left]
inserted_length = "110 mm"
clearance = "0.5 mm"
shaft_diameter = "60 mm"
shaft_length = "150 mm"
expansion_pressure = "6 bar"
[[supports.left.expanding]]
center = "70 mm"
width = "60 mm"
segments = )" +
           std::to_string(segments) +
           R"(
segment_angle = "60 deg"
[mesh]
level = "coarse"
[analysis]
modes = 8
)";
}

LimitsRequest one_diameter(double d) {
    LimitsRequest r;
    r.spec.largest_diameter_m = r.spec.smallest_diameter_m = d;
    r.spec.points = 1, r.spec.band = false;
    r.check_response = false;
    return r;
}

}  // namespace

TEST_CASE("The coupled verdict: f1 from the coupled level, the spinning criteria from the axisymmetric equivalent",
          "[limits][coupled][long]") {
    const LimitsCase c = parse_limits_case_text(news_roll(3), "news.toml");
    constexpr double kD = 0.140;  // the rest roll at 140 mm
    const LimitsResult r = verdict(c.scene, c.response, one_diameter(kD));
    REQUIRE(r.points.size() == 1);
    const LimitsPoint& p = r.points.front();
    CHECK(r.level == ModelChoice::coupled);
    // f1 and k: what `coremodal run --model coupled` gives on the scene at that diameter.
    RunOptions options;
    options.quiet = true;
    options.write_results = false;
    const RunReport run = run_scene(scene_at_diameter(c.scene, kD), options);
    CHECK(p.f1_hz == Approx(run.beam.fe_first_bending_hz).epsilon(1e-9));
    REQUIRE(p.chuck_factor);
    REQUIRE(run.chuck);
    CHECK(*p.chuck_factor == Approx(run.chuck->chuck_factor).epsilon(1e-9));
    CHECK(p.at(Criterion::i5_low).web_speed_m_s == Approx(report_speeds(run).safe.at(0).v_safe_m_s).epsilon(1e-9));
    CHECK(p.at(Criterion::i5_low).level == "coupled");
    // The spinning criteria: `limits --model harmonic` on the equivalent scene.
    Scene equivalent = axisymmetric_equivalent(c.scene).scene;
    equivalent.model = ModelChoice::harmonic;
    const LimitsResult h = verdict(equivalent, c.response, one_diameter(kD));
    REQUIRE(p.equivalent_f1_hz);
    CHECK(*p.equivalent_f1_hz == Approx(h.points.front().f1_hz).epsilon(1e-9));
    for (Criterion k :
         {Criterion::order1_backward, Criterion::order1_forward, Criterion::order2, Criterion::amplitude}) {
        const CriterionSpeed &a = p.at(k), &b = h.points.front().at(k);
        INFO(criterion_name(k));
        CHECK(a.given == b.given);
        if (a.given) CHECK(a.web_speed_m_s == Approx(b.web_speed_m_s).epsilon(1e-9));
        CHECK(a.level == "harmonic, axisymmetric equivalent (pads' coverage 50 %)");
    }
    // The pads are softer than the full band the coupled level's K splits off,
    // and stiffer than nothing: the equivalent's f1 within a few per cent.
    CHECK(*p.equivalent_f1_hz == Approx(p.f1_hz).epsilon(0.05));
    bool echoed = false;
    for (const std::string& a : r.assumptions) echoed = echoed || a.rfind("axisymmetric equivalent", 0) == 0;
    CHECK(echoed);
}

TEST_CASE("The coupled verdict refuses two pads before any work, with the reason", "[limits][coupled]") {
    const LimitsCase c = parse_limits_case_text(news_roll(2), "news.toml");
    CHECK_THROWS_WITH(require_limits_scene(c.scene, one_diameter(0.14)),
                      Catch::Contains("news.toml") && Catch::Contains("segments >= 3"));
}
