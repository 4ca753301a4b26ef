// The chuck factor of a scene and its calibration law (beam/chuck_calibration.hpp),
// on synthetic data where the answer is known.
#include "beam/chuck_calibration.hpp"

#include "common/error.hpp"
#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace coremodal;

namespace {

const std::string kClamped = R"(
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2 m"

[rest_paper]
thickness = "20 mm"

[supports]
type = "clamped"

[supports.left]
length = "70 mm"
center = "100 mm"

[supports.right]
length = "70 mm"
center = "140 mm"
)";

// Samples of a known law on a grid of groups.
std::vector<CalibrationSample> samples_of(const ChuckFactorLaw& law) {
    std::vector<CalibrationSample> out;
    for (double g1 : {0.02, 0.1, 0.3})
        for (double g2 : {0.002, 0.01})
            for (double g3 : {0.3, 0.7, 0.9}) {
                const CalibrationGroups g{g1 + 0.01 * g3, g2 * (1 + g1), g3};  // not a product grid
                out.push_back({g, law.k(g)});
            }
    return out;
}

}  // namespace

TEST_CASE("Li of a clamped scene is the mean of the clamp centres, each from its own end; k = f1 / I-7",
          "[beam][calibration]") {
    const Scene s = parse_case_text(kClamped, "c.toml");
    CHECK(*scene_li(s) == Approx(0.12));
    const ChuckFactorI7 c = *chuck_factor_of(s, 50.0);
    CHECK(c.span_m == Approx(2 - 0.24));
    CHECK(c.f_i7_hz == Approx(euler_bernoulli_first_bending_hz(beam_section(s), 1.76)));
    CHECK(c.k == Approx(50.0 / c.f_i7_hz));
    const CalibrationGroups g = calibration_groups(s, c.li_m, c.span_m);
    const BeamSection b = beam_section(s);
    CHECK(g.g1 == Approx(b.EI / core_bending_stiffness(s) * 0.12 / 1.76));
    CHECK(g.g2 == Approx(b.EI / (b.kappa_GA * 1.76 * 1.76)));
    CHECK(g.g3 == Approx(1 - core_bending_stiffness(s) / b.EI));
    SECTION("A free scene has no Li and no chuck factor") {
        const Scene free = parse_case_text("[core]\ninner_diameter = \"76 mm\"\nwall = \"15 mm\"\nlength = \"2 m\"\n",
                                           "f.toml");
        CHECK_FALSE(scene_li(free));
        CHECK_FALSE(chuck_factor_of(free, 50.0));
    }
}

TEST_CASE("The fit recovers a law it is given exactly", "[beam][calibration]") {
    ChuckFactorLaw truth;
    truth.c = {0.95, 4.0, 30.0, 1.2};
    const ChuckFactorLaw fit = fit_chuck_factor(samples_of(truth));
    for (size_t i = 0; i < 4; ++i) CHECK(fit.c[i] == Approx(truth.c[i]).epsilon(1e-8));
    CHECK(fit.k({0.1, 0.005, 0.5}) == Approx(truth.k({0.1, 0.005, 0.5})));
}

TEST_CASE("A group that never changes is left out; groups that move together are refused", "[beam][calibration]") {
    ChuckFactorLaw truth;
    truth.c = {1.05, 5.0, 20.0, 0.0};
    SECTION("Bare cores: g3 = 0 everywhere") {
        std::vector<CalibrationSample> s;
        for (double g1 : {0.02, 0.05, 0.1})
            for (double g2 : {0.002, 0.004})
                s.push_back({{g1, g2 + g1 * g1, 0.0}, truth.k({g1, g2 + g1 * g1, 0.0})});
        const ChuckFactorLaw fit = fit_chuck_factor(s);
        CHECK_FALSE(fit.fitted[2]);
        CHECK(fit.c[3] == 0);
        CHECK(fit.c[1] == Approx(5.0));
    }
    SECTION("g2 proportional to g1") {
        std::vector<CalibrationSample> s;
        for (double g1 : {0.02, 0.05, 0.1, 0.2, 0.3})
            for (double g3 : {0.2, 0.5}) s.push_back({{g1, 0.1 * g1, g3}, 0.8});
        CHECK_THROWS_WITH(fit_chuck_factor(s), Catch::Contains("do not vary the groups"));
    }
    SECTION("Too few points") {
        CHECK_THROWS_WITH(fit_chuck_factor({{{0.1, 0.01, 0.5}, 0.8}}), Catch::Contains("needs at least"));
    }
}

TEST_CASE("A calibration file round-trips; a file that is not one is refused by name", "[beam][calibration]") {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("cal_" + std::to_string(::getpid()) + ".toml")).string();
    Calibration c;
    c.law.c = {0.9, 3.0, 40.0, 1.1};
    c.case_name = "stand";
    c.g1 = {0.01, 0.3}, c.g2 = {0.001, 0.02}, c.g3 = {0.2, 0.9};
    c.span_m = {1, 2}, c.li_m = {0.035, 0.035}, c.diameter_m = {0.11, 0.19};
    c.n_fit = 9, c.n_held_out = 3, c.stated_error = 0.05, c.max_error_held_out = 0.02, c.passed = true;
    write_calibration(path, c);
    const Calibration r = read_calibration(path);
    CHECK(r.law.c == c.law.c);
    CHECK(r.case_name == "stand");
    CHECK(r.g3.max == c.g3.max);
    CHECK(r.passed);
    CHECK(r.stated_error == 0.05);

    SECTION("A point outside the calibrated ranges is noted, not refused") {
        std::vector<std::string> notes;
        const double k = calibrated_k(r, {0.5, 0.01, 0.5}, 3.0, 0.035, 0.15, notes);
        CHECK(k == Approx(c.law.k({0.5, 0.01, 0.5})));
        CHECK(notes.size() == 2);  // L = 3 m and g1 = 0.5
        CHECK_THAT(notes[0], Catch::Contains("outside the calibrated range"));
    }
    SECTION("Another file") {
        std::ofstream(path) << "format = \"something\"\nversion = 1\n";
        CHECK_THROWS_WITH(read_calibration(path), Catch::Contains("format is not \"coremodal-calibration\""));
        std::ofstream(path) << "format = \"coremodal-calibration\"\nversion = 9\n";
        CHECK_THROWS_WITH(read_calibration(path), Catch::Contains("version 9 is not supported"));
    }
    std::filesystem::remove(path);
}
