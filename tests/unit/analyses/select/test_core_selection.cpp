// The core-selection chart's numbers against hand calculations: the weight
// a core carries (durability curve, chuck scaling, winder), the widest rest
// roll by I-5 with I-7 (solved for the span in closed form), never narrower
// than the limits verdict's width (tests/unit/analyses/select/test_rest_roll_limit.cpp),
// a paper roll's mass, and which cores pass a reel.
#include "common/error.hpp"
#include "analyses/select/core_selection.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace coremodal;

namespace {

// Two grades given by fitted values, a news-like stand and two reels.
const std::string kSelection = R"(
[selection]
paper_density = "750 kg/m^3"
rest_paper_modulus = "5 GPa"
rest_paper_density = "1350 kg/m^3"
[[selection.core]]
name = "thin"
inner_diameter = "76 mm"
outer_diameter = "100 mm"
flexural_modulus = "4 GPa"
density = "700 kg/m^3"
price_per_m = 3
b0 = "20 kN"
b1 = -0.1
s_log = 0.05
test_chuck_length = "100 mm"
[[selection.core]]
name = "thick"
inner_diameter = "76 mm"
outer_diameter = "106 mm"
flexural_modulus = "5 GPa"
density = "800 kg/m^3"
price_per_m = 2
b0 = "30 kN"
b1 = -0.1
s_log = 0.05
test_chuck_length = "100 mm"
[[selection.stand]]
name = "news"
chuck_length = "110 mm"
chuck_factor = 0.85
rest_roll_diameter = "120 mm"
roll_diameter = "1000 mm"
[[selection.stand]]
name = "gravure"
chuck_length = "200 mm"
chuck_factor = 0.85
winder = "centre"
rest_roll_diameter = "200 mm"
roll_diameter = "1250 mm"
cores = ["thick"]
[[selection.reel]]
stand = "news"
width = "1.5 m"
diameter = "1000 mm"
[[selection.reel]]
stand = "news"
width = "2.6 m"
diameter = "1000 mm"
)";

std::string error_of(const std::string& text) {
    try {
        read_selection_text(text, "s.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("a core's weight limit is its reduced curve scaled by the chuck length and the winder", "[selection]") {
    const SelectionScene s = read_selection_text(kSelection, "s.toml");
    // {32} at one cycle: 30 kN 10^(lambda 0.05), lambda(1e-5) = -4.264891.
    const double at_test_chuck = 30e3 * std::pow(10.0, -4.264891 * 0.05);
    const WeightLimit news = core_weight_limit(s.cores[1], s.stands[0], s);
    CHECK(news.test_chuck_weight_n == Approx(at_test_chuck).epsilon(1e-6));
    CHECK(news.chuck_scale == Approx(1.1));  // 110 mm / 100 mm, exponent 1
    CHECK(news.winder_factor == 1.0);
    const WeightLimit gravure = core_weight_limit(s.cores[1], s.stands[1], s);
    CHECK(gravure.weight_n == Approx(at_test_chuck * 2.0 * 0.8).epsilon(1e-6));  // 200/100 mm, centre winder -20 %
    // Without the chuck-length scaling (exponent 0) the stand's chuck does not matter.
    Stand flat = s.stands[1];
    flat.chuck_length_exponent = 0;
    CHECK(core_weight_limit(s.cores[1], flat, s).weight_n == Approx(at_test_chuck * 0.8));
}

TEST_CASE("the I-7 width estimate is I-5 with I-7 solved for the span", "[selection]") {
    const SelectionScene s = read_selection_text(kSelection, "s.toml");
    const CoreGrade& c = s.cores[0];
    const Stand& st = s.stands[0];
    // By hand: EI and rho A of core plus rest paper, then
    // v = safe pi Dp k 22.373/(2 pi) sqrt(EI/rhoA) / L^2 = v_target for L.
    const double pi = std::numbers::pi;
    const double di = 0.076, d0 = 0.100, dp = 0.120;
    const double ei = 4e9 * pi / 64 * (std::pow(d0, 4) - std::pow(di, 4)) +
                      5e9 * pi / 64 * (std::pow(dp, 4) - std::pow(d0, 4));
    const double rho_a = 700 * pi / 4 * (d0 * d0 - di * di) + 1350 * pi / 4 * (dp * dp - d0 * d0);
    const double span = std::sqrt(0.7 * pi * dp * 0.85 * std::pow(4.730040744862704, 2) / (2 * pi) * std::sqrt(ei / rho_a) / 15.0);
    const double width = span + 2 * 0.055;  // li: the middle of the 110 mm chuck
    CHECK(i7_max_width(c, st, s, 15.0) == Approx(width).epsilon(1e-12));
}

TEST_CASE("a paper roll's mass is its core's and its paper's by hand", "[selection]") {
    const SelectionScene s = read_selection_text(kSelection, "s.toml");
    const double pi = std::numbers::pi;
    const double expected = (700 * pi / 4 * (0.1 * 0.1 - 0.076 * 0.076) + 750 * pi / 4 * (1.0 - 0.1 * 0.1)) * 2.5;
    CHECK(paper_roll_mass(s.cores[0], 1.0, 2.5, 750) == Approx(expected).epsilon(1e-12));
}

TEST_CASE("the reels' verdicts, the lightest and the cheapest core that pass", "[selection]") {
    const SelectionScene s = read_selection_text(kSelection, "s.toml");
    const SelectionResult r = select_cores(s);
    REQUIRE(r.reels.size() == 2);
    CHECK_FALSE(r.table[1][0].fits);  // the gravure stand takes "thick" only
    CHECK(r.table[1][1].fits);
    // Reel 1: 1.5 m x 1 m, about 900 kg, within both cores' weight and speed.
    const ReelCheck& small = r.reels[0];
    CHECK(small.cores[0].passes());
    CHECK(small.cores[1].passes());
    CHECK(*small.lightest == 0);  // "thin" weighs less per metre
    CHECK(*small.cheapest == 1);  // "thick" costs less per metre
    // Reel 2: 2.6 m is past both rest rolls' speed width in the news stand.
    const ReelCheck& wide = r.reels[1];
    CHECK(r.table[0][0].speed_width_m < 2.6);
    CHECK_FALSE(wide.cores[0].speed_ok);
    CHECK_FALSE(wide.lightest.has_value());
    // The chart's corner: the smaller of the two widths, and which one governs.
    for (const CoreInStand& c : r.table[0]) {
        CHECK(c.max_width_m == std::min(c.speed_width_m, c.weight_width_m));
        CHECK(c.max_mass_kg * kStandardGravityForWeight == Approx(c.weight.weight_n));
        // The verdict's I-5 has I-7's f1 (the calibration) and other criteria beside it.
        CHECK(c.speed_width_m <= c.i7_width_m * (1 + kCalibrationTolerance) + kWidthTolerance);
        CHECK_FALSE(c.speed_verdict.governing.empty());
    }
}

TEST_CASE("a bad selection file is refused with its place and what is expected", "[selection]") {
    auto with = [](const std::string& from, const std::string& to) {
        std::string t = kSelection;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    CHECK_THAT(error_of(with("chuck_factor = 0.85\nrest", "chuck_factr = 0.85\nrest")),
               Catch::StartsWith("s.toml:31:1: unknown key 'chuck_factr' in [[selection.stand]]; did you mean 'chuck_factor'"));
    CHECK_THAT(error_of(with("stand = \"news\"\nwidth = \"1.5 m\"", "stand = \"offset\"\nwidth = \"1.5 m\"")),
               Catch::Contains("[[selection.reel]] stand = \"offset\": expected the name of a [[selection.stand]]"));
    CHECK_THAT(error_of(with("b0 = \"20 kN\"", "b0 = 20")),
               Catch::Contains("b0 = 20: expected a weight with its unit, e.g. \"28 kN\""));
    CHECK_THAT(error_of(with("price_per_m = 3\n", "price_per_m = 3\ndurability = \"x.csv\"\n")),
               Catch::Contains("give either durability = \"file.csv\" or b0"));
    CHECK_THAT(error_of(with("width = \"2.6 m\"", "width = \"0.1 m\"")),
               Catch::Contains("width = 100 mm leaves no free span between the chucks of stand news"));
    // Wider than 2 li but narrower than the two 110 mm chucks.
    CHECK_THAT(error_of(with("width = \"2.6 m\"", "width = \"0.2 m\"")),
               Catch::Contains("width = 200 mm leaves no free span between the chucks of stand news "
                               "(2 x max(li, chuck_length) = 220 mm)"));
    CHECK_THAT(error_of(with("chuck_factor = 0.85\nwinder", "chuck_factor = 1.2\nwinder")),
               Catch::Contains("chuck_factor = 1.2: out of range"));
    CHECK_THAT(error_of(with("cores = [\"thick\"]", "cores = [\"thik\"]")),
               Catch::Contains("cores: \"thik\" is not a [[selection.core]] name"));
    CHECK_THAT(error_of("[selection]\npaper_density = \"750 kg/m^3\"\n"),
               Catch::StartsWith("s.toml:") && Catch::Contains("rest_paper_modulus is missing"));
}
