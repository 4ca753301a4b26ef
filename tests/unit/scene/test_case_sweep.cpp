// The [study] and [calibration] tables (scene/case_sweep.hpp): the grid, the
// scenes of its points, and every way the table can be wrong.
#include "scene/case_sweep.hpp"

#include "common/error.hpp"
#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;

namespace {

const std::string kFile = "cases/s.toml";

// A clamped rest roll; tests append a [study] table.
const std::string kCase = R"(name = "s"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2 m"

[rest_paper]
outer_diameter = "150 mm"

[supports]
type = "clamped"

[supports.left]
length = "70 mm"
center = "100 mm"
)";

CaseSweep sweep_of(const std::string& study, const std::optional<std::string>& mesh = std::nullopt) {
    return CaseSweep::from_text(kCase + study, kFile, "study", mesh);
}

std::string error_of(const std::string& study, const std::string& base = kCase) {
    try {
        CaseSweep::from_text(base + study, kFile, "study");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("A grid of two parameters: the first varies slowest, each point has a predecessor one step back",
          "[scene][sweep]") {
    const CaseSweep s = sweep_of(R"(
[study]
parameters = [
  { key = "rest_paper.thickness", values = ["5 mm", "20 mm"] },
  { key = "core.length", from = "1 m", to = "2 m", steps = 3 },
]
)");
    REQUIRE(s.n_points() == 6);
    CHECK(s.parameters()[0].name == "rest_paper.thickness");
    CHECK(s.parameters()[0].si == std::vector<double>{0.005, 0.02});
    CHECK(s.parameters()[1].si == std::vector<double>{1.0, 1.5, 2.0});
    CHECK(s.value_indices(4) == std::vector<int>{1, 1});
    CHECK(s.describe(4) == "rest_paper.thickness = 20 mm, core.length = 1.5 m");
    CHECK_FALSE(s.predecessor(0));
    CHECK(*s.predecessor(1) == 0);  // along the fastest parameter
    CHECK(*s.predecessor(3) == 0);  // first of a line: the first of the previous line
    CHECK(*s.predecessor(5) == 4);

    SECTION("Each point is the case with the keys set, read by the case reader") {
        const Scene p = s.scene(4);
        CHECK(p.core.length == Approx(1.5));
        // thickness replaces the case's outer_diameter (the reader accepts one of them)
        CHECK(p.rest_paper->outer_diameter == Approx(0.106 + 2 * 0.020));
        // The right clamp mirrors the left one on every length.
        CHECK(p.supports.clamps[1].z_end == Approx(1.5 - 0.065));
    }
    SECTION("A study's defaults: coarse mesh and 12 modes when the case does not say") {
        const Scene p = s.scene(0);
        CHECK(p.mesh.level == "coarse");
        CHECK(p.analysis.n_modes == kStudyDefaultModes);
        CHECK(s.options().mesh_level == "coarse");
    }
}

TEST_CASE("Study options: mesh and modes of the table, --mesh over both, the case's own when the table is silent",
          "[scene][sweep]") {
    const std::string table = "\n[study]\nparameters = [{ key = \"core.length\", values = [\"1 m\"] }]\n";
    CHECK(sweep_of(table + "mesh = \"fine\"\nmodes = 7\n").scene(0).mesh.level == "fine");
    CHECK(sweep_of(table + "modes = 7\n").scene(0).analysis.n_modes == 7);
    CHECK(sweep_of(table + "mesh = \"fine\"\n", std::string("default")).scene(0).mesh.level == "default");
    const std::string own = kCase + "\n[mesh]\naround = 24\n\n[analysis]\nband = [\"0 Hz\", \"900 Hz\"]\n" + table;
    const Scene p = CaseSweep::from_text(own, kFile, "study").scene(0);
    CHECK(p.mesh.n_around == 24);
    CHECK(p.analysis.f_max_hz);
}

TEST_CASE("Keys reach into materials, lists of keys move together, integers and log ranges", "[scene][sweep]") {
    SECTION("A library material by name gets one value changed") {
        const CaseSweep s = sweep_of(
            "\n[study]\nparameters = [{ key = \"core.material.G_rz\", values = [\"50 MPa\", \"200 MPa\"] }]\n");
        const Scene p = s.scene(1);
        CHECK(p.core.material.G_rz == Approx(200e6));
        CHECK(p.core.material.E_z == Approx(6.5e9));  // the rest from the library
    }
    SECTION("Both clamps move with one parameter") {
        const CaseSweep s = sweep_of(R"(
[supports.right]
length = "70 mm"
center = "100 mm"

[study]
parameters = [{ key = ["supports.left.center", "supports.right.center"], values = ["150 mm"] }]
)");
        const Scene p = s.scene(0);
        CHECK(p.supports.clamps[0].z_start == Approx(0.115));
        CHECK(p.supports.clamps[1].z_end == Approx(2 - 0.115));
    }
    SECTION("Integer ranges and log spacing") {
        const CaseSweep s = sweep_of(R"(
[study]
parameters = [
  { key = "mesh.around", from = 16, to = 32, steps = 3 },
  { key = "core.length", from = "1 m", to = "4 m", steps = 3, spacing = "log" },
]
)");
        CHECK(s.parameters()[0].labels == std::vector<std::string>{"16", "24", "32"});
        CHECK(s.parameters()[1].si[1] == Approx(2.0));
        CHECK(s.scene(8).mesh.n_around == 32);
    }
}

TEST_CASE("A combination the case reader refuses fails at its point, naming the point", "[scene][sweep]") {
    const CaseSweep s = sweep_of("\n[study]\nparameters = [{ key = \"core.length\", values = [\"2 m\", \"0.15 m\"] }]\n");
    CHECK_NOTHROW(s.scene(0));
    try {
        s.scene(1);
        FAIL("expected an InputError");
    } catch (const InputError& e) {
        const std::string msg = e.what();
        CHECK_THAT(msg, Catch::Contains("point 2 (core.length = 0.15 m)"));
        CHECK_THAT(msg, Catch::Contains("[supports.left]"));
    }
}

TEST_CASE("Bad [study] tables are refused with file, line, key and what is expected", "[scene][sweep]") {
    SECTION("No [study] table") {
        CHECK_THAT(error_of(""), Catch::Contains("cases/s.toml: no [study] table"));
    }
    SECTION("An unknown key of [study], with a suggestion") {
        CHECK_THAT(error_of("\n[study]\nparameter = []\n"),
                   Catch::Contains("cases/s.toml:19:1: unknown key 'parameter' in [study]; did you mean 'parameters'?"));
    }
    SECTION("A key path that is not in the schema") {
        const std::string e =
            error_of("\n[study]\nparameters = [{ key = \"rest_paper.thikness\", values = [\"5 mm\"] }]\n");
        CHECK_THAT(e, Catch::Contains("cases/s.toml:19:23:"));
        CHECK_THAT(e, Catch::Contains("no key 'thikness' in [rest_paper]; did you mean 'thickness'?"));
    }
    SECTION("A path that names a table, not a value") {
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"core\", values = [1] }]\n"),
                   Catch::Contains("[core] is not a single value"));
    }
    SECTION("A value of the wrong dimension points at that value") {
        const std::string e =
            error_of("\n[study]\nparameters = [{ key = \"core.length\", values = [\"2 m\", \"3 kg\"] }]\n");
        CHECK_THAT(e, Catch::Contains("cases/s.toml:19:55:"));
        CHECK_THAT(e, Catch::Contains("unit 'kg' is a mass, expected a length"));
    }
    SECTION("A value out of the schema's range: the case reader's words (one check, case_schema's out_of_range)") {
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"core.length\", values = [\"-2 m\"] }]\n"),
                   Catch::Contains("(core.length) = -2 m must be positive"));
    }
    SECTION("Values and a range together, or neither") {
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"core.length\", values = [1], from = 1, to = 2, "
                            "steps = 2 }]\n"),
                   Catch::Contains("gives values and a range"));
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"core.length\" }]\n"), Catch::Contains("has no values"));
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"core.length\", from = 1, to = 2 }]\n"),
                   Catch::Contains("a range needs from, to and steps"));
    }
    SECTION("An integer range that does not land on whole numbers") {
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"mesh.around\", from = 16, to = 32, steps = 4 }]\n"),
                   Catch::Contains("not a whole number"));
    }
    SECTION("The same key twice") {
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"core.length\", values = [1] }, { key = "
                            "\"core.length\", values = [2] }]\n"),
                   Catch::Contains("is varied twice"));
    }
    SECTION("An unknown mesh level, and a mesh level on a case with its own mesh file") {
        CHECK_THAT(error_of("\n[study]\nmesh = \"corse\"\nparameters = [{ key = \"core.length\", values = [1] }]\n"),
                   Catch::Contains("unknown mesh level"));
    }
    SECTION("A word the case reader does not know is refused at its line") {
        const std::string e =
            error_of("\n[study]\nparameters = [{ key = \"mesh.level\", values = [\"coarse\", \"corse\"] }]\n");
        CHECK_THAT(e, Catch::Contains("cases/s.toml:19:57: [study] parameters #1 (mesh.level) = corse is refused"));
        CHECK_THAT(e, Catch::Contains("did you mean \"coarse\"?"));
    }
    SECTION("A material value must be a library name") {
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"core.material\", values = [{ E = 1 }] }]\n"),
                   Catch::Contains("core.material.E_z"));
    }
    SECTION("The base case itself is checked as for `run`") {
        CHECK_THAT(error_of("\n[study]\nparameters = [{ key = \"core.length\", values = [1] }]\n",
                            "[core]\ninner_diameter = \"76 mm\"\nwall = \"15 mm\"\n"),
                   Catch::Contains("length is missing"));
    }
}

TEST_CASE("`run` reads a case with [study] and [calibration] tables and ignores them", "[scene][sweep]") {
    const Scene s = parse_case_text(kCase + "\n[study]\nparameters = [{ key = \"x\", values = [1] }]\n"
                                            "\n[calibration]\nholdout_every = 3\n",
                                    kFile);
    CHECK(s.core.length == Approx(2.0));
}

TEST_CASE("[calibration] has its own options and defaults", "[scene][sweep]") {
    const CaseSweep s = CaseSweep::from_text(
        kCase + "\n[calibration]\nholdout_every = 3\nmax_error = 0.02\nparameters = [{ key = \"core.length\", "
                "values = [\"1 m\", \"2 m\"] }]\n",
        kFile, "calibration");
    CHECK(s.options().holdout_every == 3);
    CHECK(s.options().max_error == Approx(0.02));
    CHECK(s.options().modes == kCalibrationDefaultModes);
    try {
        CaseSweep::from_text(kCase + "\n[calibration]\nweb_speed = \"14 m/s\"\n", kFile, "calibration");
        FAIL("expected an InputError");
    } catch (const InputError& e) {
        CHECK_THAT(std::string(e.what()), Catch::Contains("unknown key 'web_speed' in [calibration]"));
    }
}

TEST_CASE("The example study (case 06) reads: 4 widths x 10 thicknesses, every point a valid scene",
          "[scene][sweep][cases]") {
    const CaseSweep s = CaseSweep::read(std::string(COREMODAL_SOURCE_DIR) + "/cases/06-study-safe-speed.toml", "study");
    REQUIRE(s.n_points() == 40);
    CHECK(s.options().web_speed_m_s == Approx(14.0));
    CHECK(s.options().modes == 8);
    CHECK(s.parameters()[1].labels.front() == "10 mm");
    for (int i = 0; i < s.n_points(); ++i) CHECK_NOTHROW(s.scene(i));
}

namespace {

// The case reader's message for `core.length = VALUE` in an otherwise good
// case, from "= " on (the sweep names the key by its parameter and path, the
// reader by its table, and their file positions differ).
std::string reader_words(const std::string& value) {
    std::string text = kCase;
    text.replace(text.find("length = \"2 m\""), std::string("length = \"2 m\"").size(), "length = " + value);
    try {
        parse_case_text(text, kFile);
    } catch (const InputError& e) {
        const std::string what = e.what();
        return what.substr(what.find("= "));
    }
    return "(no error)";
}

std::string sweep_words(const std::string& value) {
    const std::string what = error_of("\n[study]\nparameters = [{ key = \"core.length\", values = [" + value + "] }]\n");
    return what.substr(what.find("(core.length) = ") + std::string("(core.length) ").size());
}

}  // namespace

TEST_CASE("A swept value out of range is refused in the case reader's words", "[scene][sweep]") {
    // [core] length is > 0 and at most 50 m (case_key_ranges.hpp: kMaxLength, a
    // unit slip's bound), so -2 m, 60 m and a plain 76 (76 m, meant as mm)
    // are out of range with the messages written out here.
    const std::string negative = "= -2 m must be positive";
    const std::string too_long = "= 60 m is too large: expected at most 50 m";
    const std::string plain =
        "= 76 m is too large: expected at most 50 m; plain numbers are in m, for millimetres write \"76 mm\"";
    CHECK_THAT(reader_words("\"-2 m\""), Catch::StartsWith(negative));
    CHECK_THAT(sweep_words("\"-2 m\""), Catch::StartsWith(negative));
    CHECK_THAT(reader_words("\"60 m\""), Catch::StartsWith(too_long));
    CHECK_THAT(sweep_words("\"60 m\""), Catch::StartsWith(too_long));
    CHECK_THAT(reader_words("76"), Catch::StartsWith(plain));
    CHECK_THAT(sweep_words("76"), Catch::StartsWith(plain));
    CHECK(sweep_words("76") == reader_words("76"));
    // Integer keys alike: [analysis] modes is 1 to 10000.
    const std::string modes =
        error_of("\n[analysis]\nmodes = 12\n[study]\nparameters = [{ key = \"analysis.modes\", values = [0] }]\n");
    CHECK_THAT(modes, Catch::Contains("(analysis.modes) = 0 is out of range; expected 1 to 10000"));
}
