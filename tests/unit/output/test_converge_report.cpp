// The converge report files (output/converge_report.hpp) on synthetic
// ladders: every level and tracked mode in converge.csv, the study in
// converge.json, the tables and model errors in converge.md, the console
// summary.
#include "output/converge_report.hpp"

#include "analyses/converge/ladder_runs.hpp"  // progress_seconds

#include "support/json_lookup.hpp"  // json_number, json_string: read back converge.json
#include "output/csv.hpp"

#include "support/converge_levels.hpp"
#include "support/test_modes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace coremodal;
using coremodal::testing::level;
using coremodal::testing::mode;

TEST_CASE("The report files hold every level and tracked mode", "[converge]") {
    std::vector<LevelResult> levels;
    for (int k = 1; k <= 4; ++k) {
        const double e = std::pow(1.0 / k, 4);
        levels.push_back(level(k, {mode(1, 61.3 + e, "bending", 1, 0), mode(2, 61.3 + e, "bending", 1, 0),
                                   mode(3, 430 + 50 * e, "ovalling", 2, 0)}));
    }
    ConvergeStudy study;
    study.case_name = "synthetic";
    study.source_file = "synthetic.toml";
    study.n_modes = 3;
    study.repeats = 3;
    study.repeat_limit_s = 30;
    study.models.push_back(analyse_levels(ModelChoice::solid, "unit 1/1/8/10", levels));
    study.total_time_s = 99;

    const std::string csv = converge_csv(study);
    std::istringstream lines(csv);
    int n = 0;
    for (std::string line; std::getline(lines, line);) ++n;
    CHECK(n == 1 + 4 * 2);  // header + levels x tracked modes
    CHECK_THAT(csv, Catch::StartsWith("model,k,mesh,h,dofs,runs,"));
    CHECK_THAT(csv, Catch::Contains("solid,4,4/4/32/40,0.25,64000,3,"));

    const std::string json = converge_json(study);
    CHECK(json_string(json, "case.name") == "synthetic");  // the head every summary shares (schema_version 2)
    CHECK(json_string(json, "command") == "converge");
    CHECK(json_number(json, "timing_s.total").value_or(0) == Approx(99));

    const std::string md = converge_markdown(study, "");
    CHECK_THAT(md, Catch::Contains("# Convergence study: synthetic"));
    CHECK_THAT(md, Catch::Contains("| f1 (first bending) | 1.0 % | k=2"));
    CHECK_THAT(md, Catch::Contains("| f1 (first bending) | 0.10 % | k=3"));
    CHECK_THAT(md, Catch::Contains("![relative error"));
    CHECK_THAT(converge_markdown(study, "python3 missing"), Catch::Contains("(no picture: python3 missing)"));
    CHECK(study.models[0].time_exponent);
    CHECK(*study.models[0].time_exponent == Approx(1.0).epsilon(1e-9));  // time ~ k^3, DOFs ~ k^3

    std::ostringstream console;
    print_converge_summary(study, console);
    CHECK_THAT(console.str(), Catch::Contains("solid: extrapolated frequencies (three finest levels)"));
    CHECK_THAT(console.str(), Catch::Contains("f1 within  1 %: k=2"));
}

TEST_CASE("A target beyond the ladder is reported with its predicted level", "[converge]") {
    std::vector<LevelResult> levels;
    for (int k = 1; k <= 4; ++k) levels.push_back(level(k, {mode(1, 100 + 10 * std::pow(1.0 / k, 4), "ovalling", 2, 0)}));
    ConvergeStudy study;
    study.models.push_back(analyse_levels(ModelChoice::solid, "", levels));
    CHECK_THAT(converge_markdown(study, ""), Catch::Contains("predicted k ≈ 5.6"));
    std::ostringstream console;
    print_converge_summary(study, console);
    CHECK_THAT(console.str(), Catch::Contains("0.01 %: not in the ladder (k ~ 5.6"));
}

TEST_CASE("The report sets a beam level against the solid", "[converge][beam]") {
    const ConvergeStudy study = coremodal::testing::beam_against_solid_study();
    const std::string md = converge_markdown(study, "");
    CHECK_THAT(md, Catch::Contains("## Model level: beam"));
    CHECK_THAT(md, Catch::Contains("| k | elements (core/network) | DOFs | runs | network [s] |"));
    CHECK_THAT(md, Catch::Contains("| – | first ovalling | – | not in this model |"));
    CHECK_THAT(md, Catch::Contains("## Model error: beam against solid"));
    CHECK_THAT(md, Catch::Contains("- f1 (first bending): beam level converges to 62.0000 Hz (bending n=1 m=0), the "
                                   "solid to 61.3000 Hz (bending n=1 m=0): model error +1.14 %"));
    CHECK_THAT(md, Catch::Contains("- first ovalling: not in this model (rigid cross-sections); the solid converges to "
                                   "430.0000 Hz"));
    CHECK_THAT(md, Catch::Contains("0.001 |"));  // a beam level's time (1e-3 s) is not rounded to 0.00
    const std::string csv = converge_csv(study);
    CHECK_THAT(csv, Catch::Contains(",relative_error,relative_error_vs_solid\n"));
    CHECK_THAT(csv, Catch::Contains("beam,16,"));
    const std::string json = converge_json(study);
    CHECK_THAT(json, Catch::Contains("\"model_errors\""));
    CHECK_THAT(json, Catch::Contains("\"error_vs_solid\""));
    CHECK_THAT(json, Catch::Contains("\"not_in_model\""));
}

TEST_CASE("Progress seconds keep two significant digits below 0.1 s", "[converge]") {
    CHECK(progress_seconds(12.345, "%.1f") == "12.3");
    CHECK(progress_seconds(0.00123, "%.1f") == "0.0012");
    CHECK(progress_seconds(0, "%.2f") == "0.00");
}
