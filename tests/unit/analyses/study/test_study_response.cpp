// A [study] over a case with [response] (docs/how-to/studies.md, docs/how-to/response.md):
// every point runs the forced response of its own scene, which must be the
// response of that scene run alone; the summary survives the worker record;
// study.csv and report.md carry it.
#include "analyses/response/response.hpp"
#include "analyses/study/study.hpp"
#include "analyses/study/study_workers.hpp"
#include "output/study_report.hpp"
#include "scene/case_file.hpp"
#include "scene/case_sweep.hpp"
#include "scene/response_spec.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

using namespace coremodal;

namespace {

// A small clamped rest roll at the beam level, bowed, over two rest paper
// thicknesses; 2 mm limit, reached near the first resonance.
std::string roll(const std::string& thickness, const std::string& study) {
    return "model = \"beam\"\n"
           "[core]\ninner_diameter = \"150 mm\"\nouter_diameter = \"176 mm\"\nlength = \"4 m\"\n"
           "material = { E = \"6.5 GPa\", nu = 0.3, density = \"920 kg/m^3\" }\n"
           "[rest_paper]\nthickness = \"" + thickness + "\"\n"
           "material = { E = \"5 GPa\", nu = 0.3, density = \"1350 kg/m^3\" }\n"
           "[supports]\ntype = \"clamped\"\n[supports.left]\nlength = \"100 mm\"\nstart = \"0 mm\"\n"
           "[analysis]\nmodes = 8\n"
           "[damping]\nratio = 0.01\n[excitation]\nbow = \"0.5 mm\"\ngravity = false\n"
           "[response]\nweb_speeds = [\"5 m/s\", \"40 m/s\"]\npoints = 60\nlimit = \"2 mm\"\n" + study;
}

const std::string kStudy =
    "[study]\nparameters = [{ key = \"rest_paper.thickness\", values = [\"10 mm\", \"40 mm\"] }]\nweb_speed = \"14 m/s\"\n";

}  // namespace

TEST_CASE("A study over a response case runs each point's forced response", "[long][study][response]") {
    const CaseSweep sweep = CaseSweep::from_text(roll("10 mm", kStudy), "roll.toml", "study");
    std::ostringstream progress;
    StudyResult result = run_sweep(sweep, {true}, progress);
    REQUIRE(result.n_failed() == 0);
    track_modes(sweep, result);
    const char* thickness[] = {"10 mm", "40 mm"};
    for (size_t i = 0; i < 2; ++i) {
        const StudyPoint& p = result.points[i];
        REQUIRE(p.response);
        // The same scene read alone and its response run alone: the study adds nothing and loses nothing.
        const ResponseCase alone = parse_response_case_text(roll(thickness[i], ""), "roll.toml");
        const ResponseResult r = run_forced_response(alone.scene, *alone.response);
        REQUIRE(r.safe.reached);
        CHECK(p.response->limit_reached);
        CHECK(*p.response->v_limit_m_s == r.safe.web_speed_m_s);
        CHECK(*p.response->implied_factor == r.safe.implied_factor);
        CHECK(p.response->max_amplitude_m == r.max_amplitude_m);
        CHECK(p.response->limit_m == 2e-3);
        CHECK(p.response->max_web_speed_m_s == Approx(40.0).epsilon(1e-12));
        // I-5 at 0.7 and 0.8 from the response's f1 at rest, which is the point's f1 (the same beam level).
        CHECK(*p.response->v_i5_07_m_s == Approx(0.7 * M_PI * p.diameter_m * *p.f1_hz).epsilon(1e-9));
        CHECK(*p.response->v_i5_08_m_s == Approx(0.8 * M_PI * p.diameter_m * *p.f1_hz).epsilon(1e-9));
        CHECK(p.response->v_koenig_m_s);
        // The limit is reached below the resonance: an implied factor under 1, above I-5's 0.8 with this bow.
        CHECK(*p.response->implied_factor < 1.0);
        CHECK(*p.response->v_limit_m_s > *p.response->v_i5_08_m_s);
    }
    // Thicker paper, larger diameter: the limit comes at a higher web speed.
    CHECK(*result.points[1].response->v_limit_m_s > *result.points[0].response->v_limit_m_s);

    const std::string csv = study_csv(sweep, result);
    CHECK(csv.find(",v_amplitude_limit_m_s,amplitude_implied_factor,") != std::string::npos);
    const std::string report = study_report_markdown(sweep, result, {}, "switched off");
    CHECK(report.find("## Safe web speed from the forced response") != std::string::npos);
    CHECK(report.find("At the web speed 14 m/s:") != std::string::npos);
    CHECK(study_json(sweep, result, "study").find("\"response\": true") != std::string::npos);
}

TEST_CASE("A point's forced response survives the worker record; a study without [response] has none",
          "[study][response]") {
    StudyPoint p;
    p.ok = true;
    p.response = StudyResponse{};
    p.response->limit_m = 5e-3;
    p.response->max_web_speed_m_s = 30;
    p.response->limit_reached = true;
    p.response->v_limit_m_s = 16.704123456789012;
    p.response->implied_factor = 0.99958;
    p.response->max_amplitude_m = 5.155e-3;
    p.response->max_amplitude_web_speed_m_s = 16.74;
    p.response->v_i5_07_m_s = 11.69;
    p.response->v_i5_08_m_s = 13.36;  // no König: stays absent
    StudyPoint q;
    read_point_record(point_record(p), q);
    REQUIRE(q.response);
    CHECK(*q.response->v_limit_m_s == *p.response->v_limit_m_s);  // bit for bit
    CHECK(q.response->limit_reached);
    CHECK_FALSE(q.response->below_range);
    CHECK(*q.response->v_i5_08_m_s == 13.36);
    CHECK_FALSE(q.response->v_koenig_m_s);
    StudyPoint none;
    read_point_record(point_record(StudyPoint{}), none);
    CHECK_FALSE(none.response);

    // A point whose response cannot run fails with the response's reason
    // (a damped mode beyond the modes at rest the run computes).
    std::string text = roll("10 mm", kStudy);
    text.replace(text.find("ratio = 0.01\n"), 13, "ratio = 0.01\nmodes = [{ mode = 50, ratio = 0.02 }]\n");
    const CaseSweep beyond = CaseSweep::from_text(text, "roll.toml", "study");
    StudyPoint s;
    const ResponseCase c = beyond.response_case(0);
    run_point(c.scene, s, c.response);
    CHECK_FALSE(s.ok);
    INFO(s.error);
    CHECK(s.error.find("mode = 50 is not among the") != std::string::npos);
    CHECK_FALSE(s.response);
}
