#include "scene/case_file.hpp"

#include "common/error.hpp"
#include "scene/case_schema.hpp"
#include "scene/materials_library.hpp"
#include "scene/mesh_levels.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#ifndef COREMODAL_SOURCE_DIR
#define COREMODAL_SOURCE_DIR "."
#endif

using namespace coremodal;

namespace {

const std::string kFile = "cases/x.toml";

std::string case_path(const std::string& name) {
    return std::string(COREMODAL_SOURCE_DIR) + "/cases/" + name;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

// The message of the InputError that parsing `text` throws.
std::string error_of(const std::string& text, const std::string& path = kFile) {
    try {
        parse_case_text(text, path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// A valid free-free core; tests append or replace lines to break it.
const std::string kCore =
    "[core]\n"
    "inner_diameter = \"76 mm\"\n"
    "outer_diameter = \"106 mm\"\n"
    "length = \"1.5 m\"\n"
    "material = \"paperboard_core\"\n";

bool has(const std::vector<std::string>& lines, const std::string& part) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

std::string without_comments(const std::string& text) {
    std::istringstream in(text);
    std::string out, line;
    while (std::getline(in, line)) {
        // Cut at '#' outside strings: case files put no '#' inside strings.
        if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        if (!line.empty()) out += line + "\n";
    }
    return out;
}

}  // namespace

TEST_CASE("The example cases parse to the expected SI numbers", "[scene][case_file]") {
    SECTION("01: ISO free-free test of a 76x15 core") {
        const Scene s = parse_case_file(case_path("01-iso-free-free-76x15.toml"));
        CHECK(s.name == "01-iso-free-free-76x15");
        CHECK(s.core.inner_diameter == Approx(0.076));
        CHECK(s.core.outer_diameter == Approx(0.106));
        CHECK(s.core.length == Approx(1.5));
        CHECK(s.core.material.E_z == Approx(6.5e9));
        CHECK(s.core.material.density == Approx(920));
        CHECK_FALSE(s.rest_paper);
        CHECK(s.supports.kind == SupportKind::free);
        CHECK(s.supports.clamps.empty());
        CHECK(s.analysis.n_modes == 20);
        CHECK(s.mesh.level == "default");
        CHECK(s.mesh.n_wall == 3);
        CHECK(s.mesh.n_around == 32);
        // ceil(1.5 / (3 * pi * 0.106 / 32)) = ceil(48.05)
        CHECK(s.mesh.n_along == 49);
        CHECK(s.effects() == std::vector<std::string>{"core"});
        CHECK(has(s.assumptions,
                  "core material 'paperboard_core': G_rz = 130 MPa assumed (rule of thumb"));
        CHECK(has(s.assumptions,
                  "core material 'paperboard_core': E_z = 6.5 GPa from the library (Ilomäki"));
    }
    SECTION("02: clamped 76x15 core, right zone mirrors the left") {
        const Scene s = parse_case_file(case_path("02-clamped-76x15.toml"));
        CHECK(s.core.length == Approx(2.211));
        CHECK(s.analysis.n_modes == 12);
        REQUIRE(s.supports.kind == SupportKind::clamped);
        REQUIRE(s.supports.clamps.size() == 2);
        CHECK(s.supports.clamps[0].name == "left");
        CHECK(s.supports.clamps[0].z_start == Approx(0.0));
        CHECK(s.supports.clamps[0].z_end == Approx(0.070));
        CHECK(s.supports.clamps[1].name == "right");
        CHECK(s.supports.clamps[1].z_start == Approx(2.141));
        CHECK(s.supports.clamps[1].z_end == Approx(2.211));
        CHECK(s.effects() == std::vector<std::string>{"core", "rigid_clamps"});
    }
    SECTION("03: rest roll with centred clamp zones") {
        const Scene s = parse_case_file(case_path("03-rest-roll-150x15.8-4320.toml"));
        CHECK(s.core.inner_diameter == Approx(0.1505));
        CHECK(s.core.outer_diameter == Approx(0.1821));
        CHECK(s.core.length == Approx(4.32));
        REQUIRE(s.rest_paper);
        CHECK(s.rest_paper->outer_diameter == Approx(0.2021));
        CHECK(s.rest_paper->material.E_z == Approx(5.0e9));
        CHECK(s.rest_paper->material.density == Approx(1350));
        REQUIRE(s.supports.clamps.size() == 2);
        CHECK(s.supports.clamps[0].z_start == Approx(0.200));
        CHECK(s.supports.clamps[0].z_end == Approx(0.300));
        CHECK(s.supports.clamps[1].z_start == Approx(4.020));
        CHECK(s.supports.clamps[1].z_end == Approx(4.120));
        CHECK(s.mesh.n_rest_paper == 2);
        CHECK(s.mesh.n_along == 81);  // ceil(4.32 / (3 * pi * 0.1821 / 32)) = ceil(80.55)
        CHECK(s.effects() == std::vector<std::string>{"core", "rest_paper", "rigid_clamps"});
        CHECK(has(s.assumptions, "rest paper material 'rest_paper': E_r = 10 MPa assumed"));
    }
}

TEST_CASE("Geometry errors point at the value and name both keys", "[scene][case_file]") {
    SECTION("inner diameter not smaller than outer diameter") {
        const std::string text =
            "[core]\n"
            "outer_diameter = 0.106\n"
            "length = 1.5\n"
            "inner_diameter = 0.2\n";
        CHECK(error_of(text) ==
              "cases/x.toml:4:18: [core] inner_diameter = 0.2 m must be smaller than "
              "[core] outer_diameter = 0.106 m");
    }
    SECTION("zero and negative lengths") {
        CHECK_THAT(error_of("[core]\ninner_diameter = 0.076\nwall = 0.015\nlength = 0\n"),
                   Catch::Contains("cases/x.toml:4:10: [core] length = 0 m must be positive"));
        CHECK_THAT(error_of("[core]\ninner_diameter = 0.076\nwall = \"-15 mm\"\nlength = 1\n"),
                   Catch::Contains(":3:8: [core] wall = -0.015 m must be positive"));
    }
    SECTION("a plain number meant as millimetres") {
        CHECK_THAT(error_of("[core]\ninner_diameter = 76\nwall = 15\nlength = 1.5\n"),
                   Catch::Contains(":2:18: [core] inner_diameter = 76 m is too large") &&
                       Catch::Contains("for millimetres write \"76 mm\""));
    }
    SECTION("both or neither of outer_diameter and wall") {
        CHECK_THAT(
            error_of("[core]\ninner_diameter = 0.076\nouter_diameter = 0.106\nwall = 0.015\nlength "
                     "= 1\n"),
            Catch::Contains(
                ":4:8: [core] wall = 0.015 and [core] outer_diameter = 0.106 are both given"));
        CHECK_THAT(error_of("[core]\ninner_diameter = 0.076\nlength = 1\n"),
                   Catch::Contains("cases/x.toml:1:1: [core] outer_diameter is missing; expected "
                                   "outer_diameter or wall"));
    }
    SECTION("rest paper outer diameter inside the core") {
        CHECK_THAT(
            error_of(kCore + "[rest_paper]\nouter_diameter = \"95 mm\"\n"),
            Catch::Contains(":7:18: [rest_paper] outer_diameter = 0.095 m must be larger than "
                            "[core] outer_diameter = 0.106 m"));
    }
}

TEST_CASE("Missing keys and tables are named", "[scene][case_file]") {
    CHECK_THAT(error_of("name = \"x\"\n"), Catch::Contains("missing table [core]"));
    CHECK_THAT(error_of("[core]\nwall = 0.015\nlength = 1\n"),
               Catch::Contains("cases/x.toml:1:1: [core] inner_diameter is missing"));
    CHECK_THAT(error_of("[core]\ninner_diameter = 0.076\nwall = 0.015\n"),
               Catch::Contains("[core] length is missing"));
    CHECK_THAT(error_of(kCore + "[supports]\ntype = \"clamped\"\n"),
               Catch::Contains(":6:1: [supports] type = \"clamped\" needs [supports.left]"));
    CHECK_THAT(error_of(kCore + "[supports]\ntype = \"clamped\"\n[supports.left]\nstart = 0\n"),
               Catch::Contains(":8:1: [supports.left] length is missing"));
}

TEST_CASE("Unknown keys are errors that suggest the nearest key", "[scene][case_file]") {
    CHECK(
        error_of("[core]\nouter_diamter = 0.106\n") ==
        "cases/x.toml:2:1: unknown key 'outer_diamter' in [core]; did you mean 'outer_diameter'?");
    CHECK_THAT(error_of("nmae = \"x\"\n" + kCore),
               Catch::Contains(":1:1: unknown key 'nmae' at the top level; did you mean 'name'?"));
    CHECK_THAT(error_of("[cor]\n"),
               Catch::Contains("unknown key 'cor' at the top level; did you mean 'core'?"));
    CHECK_THAT(error_of(kCore + "[analysis]\nmodse = 3\n"),
               Catch::Contains(":7:1: unknown key 'modse' in [analysis]; did you mean 'modes'?"));
    CHECK_THAT(
        error_of(kCore + "[supports]\ntype = \"clamped\"\n[supports.left]\nlenght = 0.07\n"),
        Catch::Contains(":9:1: unknown key 'lenght' in [supports.left]; did you mean 'length'?"));
    CHECK_THAT(
        error_of(
            kCore +
            "[rest_paper]\nthickness = 0.01\nmaterial = { base = \"steel\", densty = 7800 }\n"),
        Catch::Contains(
            ":8:30: unknown key 'densty' in [rest_paper.material]; did you mean 'density'?"));
    SECTION("A key far from every valid one lists them instead") {
        CHECK_THAT(
            error_of(kCore + "[mesh]\ncolour = \"red\"\n"),
            Catch::Contains("unknown key 'colour' in [mesh]; expected one of level, through_wall"));
    }
    SECTION("Unknown values of choice keys suggest too") {
        CHECK_THAT(
            error_of(kCore + "[supports]\ntype = \"clamp\"\n"),
            Catch::Contains(
                ":7:8: [supports] type = \"clamp\": unknown value; did you mean \"clamped\"?"));
        CHECK_THAT(error_of(kCore + "[mesh]\nlevel = \"very-fine\"\n"),
                   Catch::Contains("did you mean \"very_fine\"?"));
        CHECK_THAT(error_of("[core]\ninner_diameter = 0.076\nwall = 0.015\nlength = 1\nmaterial = "
                            "\"paperbord_core\"\n"),
                   Catch::Contains(
                       ":5:12: [core] material = \"paperbord_core\": unknown library material; "
                       "did you mean \"paperboard_core\"?"));
    }
}

TEST_CASE("Wrong units and wrong types are named with what was expected", "[scene][case_file]") {
    CHECK_THAT(error_of("[core]\ninner_diameter = \"76 kg\"\n"),
               Catch::Contains(
                   "cases/x.toml:2:18: [core] inner_diameter = \"76 kg\": unit 'kg' is a mass, "
                   "expected a length (m, mm, cm, in)"));
    CHECK_THAT(
        error_of(
            kCore +
            "[rest_paper]\nthickness = 0.01\nmaterial = { base = \"steel\", E = \"210 GPa/m\" }\n"),
        Catch::Contains("[rest_paper.material] E = \"210 GPa/m\": unknown unit 'GPa/m'"));
    CHECK_THAT(error_of("core = \"76x15\"\n"),
               Catch::Contains(":1:8: core = \"76x15\": expected a table, written [core]"));
    CHECK_THAT(
        error_of(kCore + "[supports]\nleft = 0.07\n"),
        Catch::Contains("[supports] left = 0.07: expected a table, written [supports.left]"));
    CHECK_THAT(error_of(kCore + "[analysis]\nmodes = 2.5\n"),
               Catch::Contains(":7:9: [analysis] modes = 2.5: expected a whole number"));
    CHECK_THAT(error_of(kCore + "[analysis]\nmodes = 0\n"),
               Catch::Contains("[analysis] modes = 0 is out of range; expected 1 to 10000"));
    CHECK_THAT(error_of("name = 3\n" + kCore),
               Catch::Contains(":1:8: name = 3: expected a string"));
    CHECK_THAT(error_of("[core]\nlength = true\n"),
               Catch::Contains("[core] length = true: expected a length: a plain number in m"));
    CHECK_THAT(error_of("[core]\nmaterial = 3\n"),
               Catch::Contains("expected a library material in quotes"));
}

TEST_CASE("Materials: library, inline, overrides and admissibility", "[scene][case_file]") {
    const std::string geometry = "[core]\ninner_diameter = 0.076\nwall = 0.015\nlength = 1.5\n";
    SECTION("Every library material is admissible") {
        for (const LibraryMaterial& entry : material_library()) {
            INFO(entry.name);
            CHECK_FALSE(why_not_admissible(to_material(entry)));
        }
    }
    SECTION("A missing material takes the library default and says so") {
        const Scene s = parse_case_text(geometry, kFile);
        CHECK(s.core.material.E_z == Approx(6.5e9));
        CHECK(
            has(s.assumptions, "core material not given: library material 'paperboard_core' used"));
    }
    SECTION("An inline isotropic material") {
        const Scene s = parse_case_text(
            geometry + "material = { E = \"210 GPa\", nu = 0.3, density = \"7850 kg/m^3\" }\n",
            kFile);
        CHECK(s.core.material.E_r == Approx(210e9));
        CHECK(s.core.material.G_rz == Approx(210e9 / 2.6));
        CHECK(s.assumptions.empty());
    }
    SECTION("Overrides of a library material replace only the values given") {
        const Scene s = parse_case_text(
            geometry + "material = { base = \"paperboard_core\", G_rz = \"60 MPa\" }\n", kFile);
        CHECK(s.core.material.G_rz == Approx(60e6));
        CHECK(s.core.material.E_z == Approx(6.5e9));
        CHECK_FALSE(has(s.assumptions, "G_rz ="));
        CHECK(has(s.assumptions, "G_rtheta = 130 MPa assumed"));
        CHECK_THAT(s.core.material.source, Catch::Contains("user values for G_rz"));
    }
    SECTION("An orthotropic override of an isotropic base expands it") {
        const Scene s = parse_case_text(
            geometry + "material = { base = \"steel\", E_z = \"200 GPa\" }\n", kFile);
        CHECK(s.core.material.E_z == Approx(200e9));
        CHECK(s.core.material.E_r == Approx(210e9));
        CHECK(s.core.material.G_rz == Approx(210e9 / 2.6));
    }
    SECTION("Incomplete, mixed and mismatched inline materials are refused") {
        CHECK_THAT(
            error_of(geometry + "material = { E = \"210 GPa\", nu = 0.3 }\n"),
            Catch::Contains(
                ":5:12: [core.material] is missing density; expected all of E, nu, density"));
        CHECK_THAT(error_of(geometry + "material = { E_z = \"6 GPa\" }\n"),
                   Catch::Contains("[core.material] is missing E_r, E_theta, G_rtheta"));
        CHECK_THAT(
            error_of(geometry + "material = { E = 1e9, nu = 0.3, E_r = 1e8, density = 900 }\n"),
            Catch::Contains("[core.material] mixes isotropic keys (E, nu) with orthotropic keys"));
        CHECK_THAT(error_of(geometry + "material = { base = \"paperboard_core\", E = 1e9 }\n"),
                   Catch::Contains("base 'paperboard_core' is orthotropic"));
    }
    SECTION("Non-positive moduli and densities") {
        CHECK_THAT(
            error_of(geometry + "material = { base = \"paperboard_core\", E_z = \"-6.5 GPa\" }\n"),
            Catch::Contains(":5:46: [core.material] E_z = -6.5 GPa must be positive"));
        CHECK_THAT(error_of(geometry + "material = { base = \"steel\", density = 0 }\n"),
                   Catch::Contains("[core.material] density = 0 kg/m^3 must be positive"));
    }
    SECTION("Poisson ratios that make the compliance indefinite") {
        CHECK_THAT(error_of(geometry + "material = { base = \"paperboard_core\", nu_rz = 0.5 }\n"),
                   Catch::Contains(":5:12: [core] material is not admissible:") &&
                       Catch::Contains("not positive definite"));
        CHECK_THAT(error_of(geometry + "material = { E = 1e9, nu = 0.6, density = 900 }\n"),
                   Catch::Contains("[core] material is not admissible"));
    }
}

TEST_CASE("Clamp zones are placed from each end and checked", "[scene][case_file]") {
    const std::string clamped = kCore + "[supports]\ntype = \"clamped\"\n";
    SECTION("start and center, right given separately") {
        const Scene s =
            parse_case_text(clamped +
                                "[supports.left]\nlength = \"100 mm\"\nstart = \"50 mm\"\n"
                                "[supports.right]\nlength = \"200 mm\"\ncenter = \"300 mm\"\n",
                            kFile);
        REQUIRE(s.supports.clamps.size() == 2);
        CHECK(s.supports.clamps[0].z_start == Approx(0.05));
        CHECK(s.supports.clamps[0].z_end == Approx(0.15));
        CHECK(s.supports.clamps[1].z_start == Approx(1.1));
        CHECK(s.supports.clamps[1].z_end == Approx(1.3));
    }
    SECTION("a zone longer than the core") {
        CHECK_THAT(
            error_of(clamped + "[supports.left]\nlength = \"2 m\"\n"),
            Catch::Contains(
                ":9:10: [supports.left] ends 2 m from its core end, beyond [core] length = 1.5 m"));
    }
    SECTION("overlapping zones") {
        CHECK_THAT(error_of(clamped + "[supports.left]\nlength = \"1 m\"\n"),
                   Catch::Contains(":9:10: [supports.left] (z = 0 m to 1 m) and [supports.right] "
                                   "(z = 0.5 m to 1.5 m) overlap"));
    }
    SECTION("a centred zone reaching past the core end") {
        CHECK_THAT(error_of(clamped + "[supports.left]\nlength = \"100 mm\"\ncenter = \"20 mm\"\n"),
                   Catch::Contains(":10:10: [supports.left] center = 0.02 m with length = 0.1 m "
                                   "starts outside the core end"));
    }
    SECTION("start and center together, zero length, clamp zones on a free core") {
        CHECK_THAT(
            error_of(clamped + "[supports.left]\nlength = 0.1\nstart = 0\ncenter = 0.2\n"),
            Catch::Contains(
                "[supports.left] center = 0.2 and [supports.left] start = 0 are both given"));
        CHECK_THAT(error_of(clamped + "[supports.left]\nlength = 0\n"),
                   Catch::Contains("[supports.left] length = 0 m must be positive"));
        CHECK_THAT(
            error_of(kCore + "[supports]\ntype = \"free\"\n[supports.left]\nlength = 0.1\n"),
            Catch::Contains(":8:1: [supports.left] is given but [supports] type is \"free\""));
    }
}

TEST_CASE("Elastic chucks are read, mirrored and checked", "[scene][case_file][chucks]") {
    // kCore is 76 mm bore, 1.5 m long; lines 1-5, then [supports] on line 6.
    const std::string chucks = kCore + "[supports]\ntype = \"chucks\"\n";
    const std::string left = "[supports.left]\ninserted_length = \"110 mm\"\nclearance = \"0.5 mm\"\n";
    const std::string band = "[[supports.left.expanding]]\ncenter = \"70 mm\"\nwidth = \"60 mm\"\n";
    SECTION("a band, mirrored to the right, with derived stiffness and defaults echoed") {
        const Scene s = parse_case_text(chucks + left + band, kFile);
        REQUIRE(s.supports.kind == SupportKind::chucks);
        REQUIRE(s.supports.chucks.size() == 2);
        const ChuckSpec& c = s.supports.chucks[1];
        CHECK(c.name == "right");
        CHECK(c.body_diameter == Approx(0.075));
        CHECK(c.shaft_diameter == Approx(0.075));
        CHECK(c.li() == Approx(0.07));
        CHECK(c.interface.kind == InterfaceKind::spring);
        // k_n = K2 (p + p_res) / h = 50 x (0.6 MPa + 20 kPa) / 1 mm = 3.1e10 Pa/m.
        CHECK(c.interface.normal_stiffness == Approx(3.1e10));
        CHECK(c.interface.tangential_stiffness == Approx(3.1e10 * 2 * 0.7 / 1.7));
        CHECK(c.bearing.rigid);
        CHECK(has(s.assumptions, "rigid bearing"));
        CHECK(has(s.assumptions, "expansion pressure 600 kPa (assumed)"));
        const auto effects = s.effects();
        CHECK(std::find(effects.begin(), effects.end(), "elastic_chucks") != effects.end());
    }
    SECTION("segments, a not-expanded chuck and an elastic bearing with a frame") {
        const Scene s = parse_case_text(
            chucks + left + "expanded = false\n" +
                "[[supports.left.expanding]]\ncenter = \"70 mm\"\nwidth = \"60 mm\"\nsegments = 3\n"
                "segment_angle = \"60 deg\"\n"
                "[supports.left.bearing]\nradial_stiffness = \"200 kN/mm\"\ntilting_stiffness = \"1 MN*m/rad\"\n"
                "frame_mass = \"50 kg\"\nframe_stiffness = \"100 kN/mm\"\n",
            kFile);
        const ChuckSpec& c = s.supports.chucks[0];
        CHECK(c.expanding[0].segments == 3);
        CHECK(c.expanding[0].segment_angle == Approx(M_PI / 3));
        CHECK_FALSE(c.interface.expanded);
        CHECK(c.interface.normal_stiffness == Approx(50 * 20e3 / 1e-3));  // residual pressure only
        CHECK(c.bearing.radial_stiffness == Approx(2e8));
        CHECK(c.bearing.tilting_stiffness == Approx(1e6));
        CHECK(*c.bearing.frame_mass == Approx(50));
    }
    SECTION("an expanding element outside the inserted length") {
        CHECK_THAT(error_of(chucks + left + "[[supports.left.expanding]]\ncenter = \"100 mm\"\nwidth = \"60 mm\"\n"),
                   Catch::Contains(":12:10: [supports.left.expanding #1] spans 0.07 m to 0.13 m from the core end, "
                                   "outside the inserted length 0 to 0.11 m"));
    }
    SECTION("a chuck body larger than the bore") {
        CHECK_THAT(error_of(chucks + "[supports.left]\ninserted_length = \"110 mm\"\nbody_diameter = \"80 mm\"\n" + band),
                   Catch::Contains(":10:17: [supports.left] body_diameter = \"80 mm\" is larger than the core bore"));
    }
    SECTION("a shaft wider than the chuck body") {
        CHECK_THAT(error_of(chucks + "[supports.left]\ninserted_length = \"110 mm\"\nshaft_diameter = \"90 mm\"\n" + band),
                   Catch::Contains(":10:18: [supports.left] shaft_diameter = \"90 mm\" is wider than the chuck body"));
    }
    SECTION("a negative stiffness") {
        CHECK_THAT(error_of(chucks + left + "normal_stiffness = \"-1e10 N/m^3\"\n" + band),
                   Catch::Contains(":11:20: [supports.left] normal_stiffness = -10 GN/m^3 must be positive"));
        CHECK_THAT(error_of(chucks + left + band + "[supports.left.bearing]\nradial_stiffness = -5\n"),
                   Catch::Contains("[supports.left.bearing] radial_stiffness = -5 N/m must be positive"));
    }
    SECTION("a chuck longer than half the core") {
        CHECK_THAT(error_of(chucks + "[supports.left]\ninserted_length = \"0.8 m\"\n" + band),
                   Catch::Contains(":9:19: [supports.left] inserted_length = \"0.8 m\" is longer than half the core"));
    }
    SECTION("no expanding element, overlapping segments, unknown interface") {
        CHECK_THAT(error_of(chucks + left), Catch::Contains("[supports.left] has no expanding elements"));
        CHECK_THAT(error_of(chucks + left +
                            "[[supports.left.expanding]]\ncenter = 0.07\nwidth = 0.06\nsegments = 4\nsegment_angle = \"100 deg\"\n"),
                   Catch::Contains("overlap (more than 360 deg in all)"));
        CHECK_THAT(error_of(chucks + left + "interface = \"glued\"\n" + band),
                   Catch::Contains("[supports.left] interface = \"glued\": unknown value"));
    }
}

TEST_CASE("Analysis requests", "[scene][case_file]") {
    SECTION("a frequency band") {
        const Scene s =
            parse_case_text(kCore + "[analysis]\nband = [\"0 Hz\", \"30000 rpm\"]\n", kFile);
        CHECK(s.analysis.f_min_hz == 0.0);
        CHECK(s.analysis.f_max_hz == Approx(500.0));
    }
    SECTION("bad bands and both requests at once") {
        CHECK_THAT(error_of(kCore + "[analysis]\nband = [\"500 Hz\", \"100 Hz\"]\n"),
                   Catch::Contains("the upper frequency must be larger than the lower one"));
        CHECK_THAT(error_of(kCore + "[analysis]\nband = [\"500 Hz\"]\n"),
                   Catch::Contains("expected two frequencies"));
        CHECK_THAT(error_of(kCore + "[analysis]\nband = [\"0 Hz\", \"5 m\"]\n"),
                   Catch::Contains("unit 'm' is a length, expected a frequency"));
        CHECK_THAT(error_of(kCore + "[analysis]\nmodes = 3\nband = [0, 100]\n"),
                   Catch::Contains("are both given; expected exactly one of them"));
    }
    SECTION("tolerance and iterations") {
        const Scene s =
            parse_case_text(kCore + "[analysis]\ntolerance = 1e-8\nmax_iterations = 900\n", kFile);
        CHECK(s.analysis.tolerance == 1e-8);
        CHECK(s.analysis.max_iterations == 900);
        CHECK_THAT(error_of(kCore + "[analysis]\ntolerance = -1e-8\n"),
                   Catch::Contains("must be positive"));
    }
}

TEST_CASE("Mesh levels, explicit counts and mesh files", "[scene][case_file]") {
    SECTION("levels follow the table") {
        const Scene s = parse_case_text(kCore + "[mesh]\nlevel = \"coarse\"\n", kFile);
        CHECK(s.mesh.n_wall == 2);
        CHECK(s.mesh.n_rest_paper == 1);
        CHECK(s.mesh.n_around == 16);
        // ceil(1.5 / (4 * pi * 0.106 / 16)) = ceil(18.02)
        CHECK(s.mesh.n_along == 19);
    }
    SECTION("a short core still gets the minimum count along") {
        const Scene s =
            parse_case_text("[core]\ninner_diameter = 0.076\nwall = 0.015\nlength = 0.1\n", kFile);
        CHECK(s.mesh.n_along == kMinElementsAlong);
    }
    SECTION("explicit counts override the level and make it custom") {
        const Scene s = parse_case_text(
            kCore + "[mesh]\nlevel = \"fine\"\naround = 64\nelement = \"hex27\"\n", kFile);
        CHECK(s.mesh.level == "custom");
        CHECK(s.mesh.n_wall == 4);
        CHECK(s.mesh.n_around == 64);
        CHECK(s.mesh.n_along == *elements_along(1.5, 0.106, 64, 2.0));
        CHECK(s.mesh.element == "hex27");
        CHECK(parse_case_text(kCore + "[mesh]\nalong = 5\n", kFile).mesh.n_along == 5);
    }
    SECTION("bad counts") {
        CHECK_THAT(error_of(kCore + "[mesh]\naround = 30\n"),
                   Catch::Contains(":7:10: [mesh] around = 30 must be a multiple of 4"));
        CHECK_THAT(error_of(kCore + "[mesh]\naround = 4\n"), Catch::Contains("expected 8 to 4096"));
        CHECK_THAT(error_of(kCore + "[mesh]\nalong = 1\n"),
                   Catch::Contains("[mesh] along = 1 is out of range"));
        CHECK_THAT(error_of(kCore + "[mesh]\nelement = \"tet10\"\n"),
                   Catch::Contains(
                       "[mesh] element = \"tet10\": unknown value; expected one of hex20, hex27"));
    }
    SECTION("a mesh file is resolved against the case file's folder") {
        const auto folder = std::filesystem::temp_directory_path() / "coremodal_test_case_file";
        std::filesystem::create_directories(folder);
        std::ofstream(folder / "core.msh") << "$MeshFormat\n";
        const std::string path = (folder / "case.toml").string();
        const Scene s = parse_case_text(kCore + "[mesh]\nfile = \"core.msh\"\n", path);
        CHECK(s.mesh.file == (folder / "core.msh").string());
        CHECK_THAT(error_of(kCore + "[mesh]\nfile = \"missing.msh\"\n", path),
                   Catch::Contains(":7:8: [mesh] file = \"missing.msh\": no mesh file '" +
                                   (folder / "missing.msh").string() + "'"));
        CHECK_THAT(error_of(kCore + "[mesh]\nfile = \"core.msh\"\nlevel = \"fine\"\n", path),
                   Catch::Contains("[mesh] level = \"fine\" has no effect with [mesh] file"));
        CHECK_THAT(error_of(kCore + "[mesh]\nfile = \"core.stl\"\n", path),
                   Catch::Contains("expected a gmsh mesh file ending in .msh"));
        std::filesystem::remove_all(folder);
    }
}

TEST_CASE("Files: syntax errors and unreadable files", "[scene][case_file]") {
    CHECK_THAT(error_of("[core]\ninner_diameter = = 3\n"),
               Catch::StartsWith("cases/x.toml:2:") && Catch::Contains("TOML syntax error"));
    CHECK_THAT(error_of("[core\n"),
               Catch::StartsWith("cases/x.toml:1:") && Catch::Contains("TOML syntax error"));
    try {
        parse_case_file("/nonexistent/case.toml");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("/nonexistent/case.toml: cannot open case file"));
    }
    CHECK_THROWS_AS(parse_case_file(std::filesystem::temp_directory_path().string()), InputError);
}

TEST_CASE("Case name and description", "[scene][case_file]") {
    const Scene unnamed = parse_case_text(kCore, "some/folder/my-case.toml");
    CHECK(unnamed.name == "my-case");
    CHECK(unnamed.source_file == "some/folder/my-case.toml");
    const Scene named = parse_case_text("name = \"n\"\ndescription = \"d\"\n" + kCore, kFile);
    CHECK(named.name == "n");
    CHECK(named.description == "d");
}

TEST_CASE("Edit distance and suggestions", "[scene][case_file]") {
    CHECK(edit_distance("outer_diamter", "outer_diameter") == 1);
    CHECK(edit_distance("nmae", "name") == 1);  // a swap of neighbours counts once
    CHECK(edit_distance("", "abc") == 3);
    CHECK(nearest("lenght", keys_of("core")) == "length");
    CHECK(nearest("xyz", keys_of("core")).empty());
}

// Truncated and corrupted files must end in an InputError or a valid Scene,
// never in a crash or another exception type.
TEST_CASE("Truncated and corrupted case files never crash", "[scene][case_file][fuzz]") {
    constexpr int kTruncationsPerCase = 150;
    constexpr int kFlipsPerCase = 300;
    std::mt19937 random(20240611);  // fixed seed: a failure must be reproducible
    for (const char* name : {"01-iso-free-free-76x15.toml", "02-clamped-76x15.toml",
                             "03-rest-roll-150x15.8-4320.toml"}) {
        // Comments are most of each file; fuzz the file without them too, so
        // that most flips land in keys and values.
        for (const std::string& text :
             {read_text(case_path(name)), without_comments(read_text(case_path(name)))}) {
            REQUIRE(!text.empty());
            INFO(name << (text.front() == '#' ? "" : " without comments"));
            const auto survives = [&](const std::string& variant) {
                try {
                    parse_case_text(variant, kFile);
                } catch (const InputError&) {
                }
            };
            for (int i = 0; i <= kTruncationsPerCase; ++i) {
                const std::size_t cut = text.size() * i / kTruncationsPerCase;
                INFO("truncated at byte " << cut);
                CHECK_NOTHROW(survives(text.substr(0, cut)));
            }
            std::uniform_int_distribution<std::size_t> position(0, text.size() - 1);
            std::uniform_int_distribution<int> byte(0, 255), n_flips(1, 4);
            for (int i = 0; i < kFlipsPerCase; ++i) {
                std::string variant = text;
                for (int k = n_flips(random); k > 0; --k)
                    variant[position(random)] = static_cast<char>(byte(random));
                INFO("flip variant " << i);
                CHECK_NOTHROW(survives(variant));
            }
        }
    }
}

TEST_CASE("A case's name is a name, not a path (issue 33, 1 and 3)", "[scene][case_file][issue33]") {
    const auto with_name = [](const std::string& value) { return "name = " + value + "\n" + kCore; };
    CHECK(error_of(with_name("\"\"")) ==
          "cases/x.toml:1:8: name = \"\" is empty; expected a plain name such as \"rest-roll-300\" (letters, digits, "
          "spaces, '-', '_', '.'; no '/'), which names the results folder results/<name>");
    for (const char* bad : {"\".\"", "\"..\""})
        CHECK_THAT(error_of(with_name(bad)), Catch::Contains("which as a folder name means a folder of the path"));
    for (const char* bad : {"\"../../x\"", "\"/tmp/abs\"", "\"a/b\"", "\"a\\\\b\""})
        CHECK_THAT(error_of(with_name(bad)), Catch::Contains("is a path, not a name (it would write outside results/)"));
    CHECK_THAT(error_of(with_name("\"-x\"")), Catch::Contains("starts with '-'"));
    CHECK_THAT(error_of(with_name("\"tab\\there\"")), Catch::Contains("holds a control character"));
    CHECK_THAT(error_of(with_name("\"" + std::string(201, 'a') + "\"")), Catch::Contains("is 201 bytes long"));
    // Names that are names: spaces, dots, UTF-8.
    for (const char* good : {"\"rest roll 300\"", "\"core.v2\"", "\"..x\"", "\"Hülse 76\""})
        CHECK(parse_case_text(with_name(good), kFile).name == std::string(good).substr(1, std::string(good).size() - 2));
    // Without a name key the file's stem is the name, and it is checked too.
    CHECK_THAT(error_of(kCore, "cases/..toml"), Catch::Contains("the case's name is its file name, '.'"));
}
