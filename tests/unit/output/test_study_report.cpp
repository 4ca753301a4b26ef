// The study's tables and König's change diameters (output/study_report.hpp, analyses/study/study.hpp), on a
// study result filled by hand: no solves.
#include "output/study_report.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

const std::string kCase = R"(name = "chart"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "3 m"

[rest_paper]
thickness = "20 mm"

[supports]
type = "clamped"

[supports.left]
length = "100 mm"

[study]
web_speed = "14 m/s"
parameters = [
  { key = "core.length", values = ["2 m", "3 m"] },
  { key = "rest_paper.thickness", values = ["10 mm", "30 mm", "50 mm"] },
]
)";

// v_safe rises with D; the 3 m roll is slower: it crosses 14 m/s between
// D = 166 mm (12 m/s) and D = 206 mm (16 m/s), at 186 mm.
double v_of(double length, double d) { return length < 2.5 ? 20 + 50 * (d - 0.126) : 12 + 100 * (d - 0.166); }

StudyResult filled(const CaseSweep& sweep) {
    StudyResult r;
    for (int i = 0; i < sweep.n_points(); ++i) {
        StudyPoint p;
        p.index = i;
        p.value_index = sweep.value_indices(i);
        p.description = sweep.describe(i);
        const double length = sweep.parameters()[0].si[static_cast<size_t>(p.value_index[0])];
        const double t = sweep.parameters()[1].si[static_cast<size_t>(p.value_index[1])];
        p.diameter_m = 0.106 + 2 * t;
        p.ok = i != 1;  // point 2 failed
        if (!p.ok) {
            p.error = "solve failed: converged 3 of 8";
        } else {
            p.v_safe_m_s = v_of(length, p.diameter_m);
            p.f1_hz = *p.v_safe_m_s / (0.7 * M_PI * p.diameter_m);
            ModeSummary m;
            m.frequency_hz = *p.f1_hz;
            m.label.type = "bending";
            m.label.n = 1;
            for (int k : {1, 2}) {
                m.index = k;
                p.modes.push_back(m);
            }
        }
        r.points.push_back(p);
    }
    track_modes(sweep, r);
    return r;
}

}  // namespace

TEST_CASE("König's chart: the diameter below which each width must be changed", "[app][study]") {
    const CaseSweep sweep = CaseSweep::from_text(kCase, "chart.toml", "study");
    const StudyResult r = filled(sweep);
    CHECK(diameter_parameters(sweep, r) == std::vector<int>{1});
    const std::vector<SpeedCrossing> c = safe_speed_crossings(sweep, r, 14.0);
    REQUIRE(c.size() == 2);
    CHECK(c[0].curve == "core.length = 2 m");
    CHECK(c[0].change_diameters_m.empty());  // 20 m/s and more: safe over the range
    CHECK(c[0].v_min_m_s >= 14.0);
    CHECK(c[1].curve == "core.length = 3 m");
    REQUIRE(c[1].change_diameters_m.size() == 1);
    CHECK(c[1].change_diameters_m[0] == Approx(0.186));

    const std::string report = study_report_markdown(sweep, r, {"safe_speed.png"}, "");
    CHECK(report.find("core.length = 3 m: change the roll when its diameter falls below **186 mm**") !=
          std::string::npos);
    CHECK(report.find("core.length = 2 m: safe over the whole range studied") != std::string::npos);
    CHECK(report.find("## Failed points\n\n- point 2 (core.length = 2 m, rest_paper.thickness = 30 mm): solve "
                      "failed") != std::string::npos);
    CHECK(report.find("![safe_speed.png](safe_speed.png)") != std::string::npos);
}

TEST_CASE("study.csv: one row per point and tracked group, a failed point with its error", "[app][study]") {
    const CaseSweep sweep = CaseSweep::from_text(kCase, "chart.toml", "study");
    const StudyResult r = filled(sweep);
    const std::string csv = study_csv(sweep, r);
    CHECK(csv.rfind("point,core.length_m,rest_paper.thickness_m,status,predecessor,track,label,", 0) == 0);
    // The pair is one group: one row per point.
    CHECK(csv.find("\n1,2,0.01,ok,,1,bending n=1 m=0,bending,1,0,2,") != std::string::npos);
    CHECK(csv.find("\n2,2,0.03,failed,") != std::string::npos);
    CHECK(csv.find(",solve failed: converged 3 of 8\n") != std::string::npos);
    // Point 3 follows point 1 (point 2 failed), on the same track by label.
    CHECK(csv.find("\n3,2,0.05,ok,1,1,") != std::string::npos);
}
