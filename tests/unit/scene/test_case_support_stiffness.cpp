// Springs beyond rigid or beyond loose for the roll they hold, and a web's
// span so short that its stretch is beyond rigid, are refused at input with
// their place and the bound (scene/case_reader_supports.cpp, kBeyondRigid;
// issue 33, item 7: 1e300 gave "max residual inf ... complete", exit 0).
// The bound is computed here by hand from the scene's core: 1e12 times its
// axial E_z A / L (a force per displacement), E_z I / L (a moment per
// rotation), E_r / wall (per unit area), E_z A / L^2 (per unit length).
#include "scene/case_file.hpp"

#include "support/case_errors.hpp"
#include "support/program_run.hpp"  // slurp

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

namespace {

// Case 15 (chucks, the web) with `bearing` as its left chuck's [bearing] table.
std::string case_15(const std::string& bearing = "", const std::string& from = "", const std::string& to = "") {
    std::string text = coremodal::testing::slurp(std::string(COREMODAL_SOURCE_DIR) +
                                                 "/cases/15-rest-roll-on-web-76x15-2211.toml");
    if (!bearing.empty())
        text.replace(text.find("[[supports.left.expanding]]"), 0, "[supports.left.bearing]\n" + bearing + "\n\n");
    if (!from.empty()) text.replace(text.find(from), from.size(), to);
    return text;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6e", v);
    return text;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Core {
    double E_z, E_r, area, inertia, length, wall;
};

Core core_of(const Scene& s) {
    const double ro = s.core.outer_diameter / 2, ri = s.core.inner_diameter / 2;
    return {s.core.material.E_z, s.core.material.E_r, M_PI * (ro * ro - ri * ri),
            M_PI / 4 * (std::pow(ro, 4) - std::pow(ri, 4)), s.core.length, ro - ri};
}

}  // namespace

TEST_CASE("Bearing springs of 1e300 are refused at their key as beyond rigid", "[scene][stiffness]") {
    const std::string rigid_ok = "radial_stiffness = \"200 kN/mm\"\ntilting_stiffness = \"1 MN*m/rad\"";
    REQUIRE(error_of(case_15(rigid_ok)) == "(no error)");
    for (const std::string key : {"radial_stiffness", "tilting_stiffness"}) {
        INFO(key);
        std::string bearing = rigid_ok;
        const size_t at = bearing.find(key);
        bearing.replace(at, bearing.find('\n', at) == std::string::npos ? std::string::npos : bearing.find('\n', at) - at,
                        key + " = 1e300");
        const std::string e = error_of(case_15(bearing));
        CHECK_THAT(e, Catch::StartsWith("cases/x.toml:"));
        CHECK(contains(e, "[supports.left.bearing] " + key + " = 1e+300"));
        CHECK(contains(e, "is beyond rigid for this roll: more than 1e12 times the roll's own"));
        CHECK(contains(e, "expected at most"));
    }
    const std::string frame = rigid_ok + "\nframe_mass = \"80 kg\"\nframe_stiffness = 1e300";
    CHECK(contains(error_of(case_15(frame)), "frame_stiffness = 1e+300 is beyond rigid"));
}

TEST_CASE("The bound is 1e12 times the core's own stiffness of each kind, by hand", "[scene][stiffness]") {
    const Core c = core_of(parse_case_text(case_15(), "cases/x.toml"));
    const double radial = 1e12 * c.E_z * c.area / c.length;     // N/m
    const double tilting = 1e12 * c.E_z * c.inertia / c.length;  // N m/rad
    const auto bearing = [](double k_r, double k_t) {
        return "radial_stiffness = " + number(k_r) + "\ntilting_stiffness = " + number(k_t);
    };
    CHECK(error_of(case_15(bearing(0.99 * radial, 0.99 * tilting))) == "(no error)");
    CHECK(contains(error_of(case_15(bearing(1.01 * radial, 0.99 * tilting))), "radial_stiffness"));
    CHECK(contains(error_of(case_15(bearing(0.99 * radial, 1.01 * tilting))), "tilting_stiffness"));
    // Beyond loose: 1e-12 of the core's stiffness.
    CHECK(error_of(case_15(bearing(1.01e-24 * radial, 0.99 * tilting))) == "(no error)");
    CHECK(contains(error_of(case_15(bearing(0.99e-24 * radial, 0.99 * tilting))), "is beyond loose for this roll"));
}

TEST_CASE("A chuck's layer of 1e300 N/m^3 is refused; its bound is 1e12 E_r / wall", "[scene][stiffness]") {
    const Core c = core_of(parse_case_text(case_15(), "cases/x.toml"));
    const double layer = 1e12 * c.E_r / c.wall;
    const auto with = [](const std::string& k) {
        return case_15("", "expansion_pressure = \"6 bar\"", "normal_stiffness = " + k);
    };
    CHECK(error_of(with(number(0.99 * layer))) == "(no error)");
    const std::string e = error_of(with("1e300"));
    CHECK(contains(e, "[supports.left] normal_stiffness = 1e+300 is beyond rigid"));
    CHECK(contains(e, "interface = \"bonded\""));
}

TEST_CASE("A web span of 1.2e-300 m is refused: its stretch E t / s would be beyond rigid", "[scene][stiffness]") {
    const Scene s = parse_case_text(case_15(), "cases/x.toml");
    const Core c = core_of(s);
    // E t / s against 1e12 E_z A / L^2: the shortest span.
    const double shortest = s.web->modulus * s.web->thickness / (1e12 * c.E_z * c.area / (c.length * c.length));
    const auto with_span = [](const std::string& span) { return case_15("", "span = \"1.2 m\"", "span = " + span); };
    const std::string e = error_of(with_span("1.2e-300"));
    CHECK_THAT(e, Catch::StartsWith("cases/x.toml:"));
    CHECK(contains(e, "[web] span = 1.2e-300 makes the web's stretch E t / s"));
    CHECK(contains(e, "expected a span of at least"));
    CHECK(error_of(with_span(number(1.01 * shortest))) == "(no error)");
    CHECK(contains(error_of(with_span(number(0.99 * shortest))), "beyond rigid"));
}
