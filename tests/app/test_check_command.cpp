// `coremodal check`: every shipped case is valid; a bad case fails with the
// message `run` gives; a valid case's output shows each default it filled in,
// the effects and the model level with its reason (issue 11).
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

// A core and nothing else: every other table is a default.
const std::string kBareCore = R"(
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "1 m"
)";

// Whether `text` holds a line with all of `parts`, in that order.
bool has_line(const std::string& text, std::initializer_list<std::string> parts) {
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string line = text.substr(start, end - start);
        std::size_t at = 0;
        bool all = true;
        for (const std::string& p : parts) {
            at = line.find(p, at);
            if (at == std::string::npos) {
                all = false;
                break;
            }
            at += p.size();
        }
        if (all) return true;
        start = end + 1;
    }
    return false;
}

}  // namespace

TEST_CASE("Every shipped case passes coremodal check", "[app][cli][check]") {
    TempDir dir;
    for (const char* folder : {"/cases", "/cases/hard"})
        for (const auto& entry : fs::directory_iterator(COREMODAL_SOURCE_DIR + std::string(folder))) {
            if (entry.path().extension() != ".toml") continue;
            DYNAMIC_SECTION(entry.path().filename().string()) {
                const Run r = run_coremodal(dir, "check '" + entry.path().string() + "'");
                INFO("stderr: " << r.err);
                CHECK(r.exit_code == 0);
                CHECK_THAT(r.out, Catch::Contains(": valid case") || Catch::Contains(": valid two-drum winder file") ||
                                      Catch::Contains(": valid core-selection file") ||
                                      Catch::Contains(": valid traction file") ||
                                      Catch::Contains(": valid fit measurements file"));
                CHECK(r.err.empty());
            }
        }
}

TEST_CASE("A winder file: check describes it, run names the command that runs it", "[app][cli][check]") {
    TempDir dir;
    const std::string winder = COREMODAL_SOURCE_DIR + std::string("/cases/11-two-drum-winder.toml");
    const Run checked = run_coremodal(dir, "check '" + winder + "'");
    CHECK(checked.exit_code == 0);
    CHECK_THAT(checked.out, Catch::Contains("web_speed_m_s = 33.3"));  // 2000 m/min, resolved to SI
    const Run run = run_coremodal(dir, "run '" + winder + "'");
    CHECK(run.exit_code == 1);
    CHECK_THAT(run.err, Catch::Contains("11-two-drum-winder.toml:") && Catch::Contains("coremodal winder"));
    CHECK(fs::is_empty(dir.path));  // nothing written
    // check writes nothing.
    CHECK(fs::is_empty(dir.path));
}

TEST_CASE("A bad case fails coremodal check with the message coremodal run gives", "[app][cli][check]") {
    TempDir dir;
    dir.write("typo.toml", kBareCore + "outer_diamter = \"106 mm\"\n");
    dir.write("range.toml", kBareCore + "\n[analysis]\nmodes = 0\n");
    dir.write("syntax.toml", kBareCore + "\n[mesh\n");
    const std::string segmented = "'" COREMODAL_SOURCE_DIR "/cases/10-segmented-chuck-76x15-2200.toml' --model harmonic";
    for (const std::string& args : {std::string("typo.toml"), std::string("range.toml"), std::string("syntax.toml"),
                                   std::string("nothere.toml"), segmented}) {
        DYNAMIC_SECTION(args) {
            const Run check = run_coremodal(dir, "check " + args);
            const Run run = run_coremodal(dir, "run " + args + " -q --no-plots -o out");
            INFO("check stderr: " << check.err);
            CHECK(check.exit_code == 1);
            CHECK(run.exit_code == 1);
            CHECK_THAT(check.err, Catch::StartsWith("coremodal: error: "));
            CHECK(check.err == run.err);
            CHECK(check.out.empty());
        }
    }
}

TEST_CASE("coremodal check shows every default it filled in, with its origin", "[app][cli][check]") {
    TempDir dir;
    dir.write("bare.toml", kBareCore);
    const Run r = run_coremodal(dir, "check bare.toml");
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(has_line(r.out, {"name = \"bare\"", "default: the file name"}));
    CHECK(has_line(r.out, {"model = \"solid\"", "default"}));
    CHECK(has_line(r.out, {"[core] inner_diameter = 0.076 m", "file"}));
    CHECK(has_line(r.out, {"[core] outer_diameter = 0.106 m", "from wall = 0.015 m"}));
    CHECK(has_line(r.out, {"[core] material = \"paperboard_core\"", "default"}));
    CHECK(has_line(r.out, {"[core.material] E_z = 6.5 GPa", "library 'paperboard_core'"}));
    CHECK(has_line(r.out, {"[rest_paper] = none", "default"}));
    CHECK(has_line(r.out, {"[supports] type = \"free\"", "default"}));
    // No [analysis]: the number of modes is the default, 20.
    CHECK(has_line(r.out, {"[analysis] modes = 20", "default"}));
    CHECK(has_line(r.out, {"[analysis] tolerance = 1e-10", "default"}));
    CHECK(has_line(r.out, {"[mesh] level = \"default\"", "default"}));
    CHECK(has_line(r.out, {"[mesh] around = 32", "from the level"}));
    CHECK(has_line(r.out, {"effects the run simulates:"}));
    CHECK(has_line(r.out, {"  core", "0.076 m x 0.106 m, 1 m long"}));
    CHECK(has_line(r.out, {"model level: solid", "model = \"auto\" or \"harmonic\" would"}));
    CHECK(has_line(r.out, {"- core material 'paperboard_core': E_r = 33 MPa assumed"}));

    SECTION("options on the command line say so") {
        const Run coarse = run_coremodal(dir, "check bare.toml --mesh coarse --model beam");
        REQUIRE(coarse.exit_code == 0);
        CHECK(has_line(coarse.out, {"model = \"beam\"", "command line"}));
        CHECK(has_line(coarse.out, {"model level: beam (--model beam)"}));
        CHECK(has_line(coarse.out, {"[mesh] level = \"coarse\"", "command line"}));
        CHECK(has_line(coarse.out, {"[mesh] around = 16", "command line (--mesh)"}));
    }
    SECTION("a thin wall's count around is raised, and says why") {
        // 76 x 1.52 mm (hard case 01): R = 38.76 mm, t = 1.52 mm, 2 pi sqrt(R / t)
        // = 31.7; the default level's 1.5 of it is 47.6, up to a multiple of 4: 48.
        // A band below its first ring mode (thin ring: n = 2 near 300 Hz), so
        // that the band asks for nothing around (scene/mesh_rule.hpp).
        std::string thin = kBareCore + "\n[analysis]\nband = [\"0 Hz\", \"250 Hz\"]\n";
        thin.replace(thin.find("wall = \"15 mm\""), std::string("wall = \"15 mm\"").size(), "wall = \"1.52 mm\"");
        dir.write("thin.toml", thin);
        const Run t = run_coremodal(dir, "check thin.toml");
        INFO("stdout: " << t.out << "\nstderr: " << t.err);
        REQUIRE(t.exit_code == 0);
        CHECK(has_line(t.out, {"[mesh] around = 48", "from the level: its 32 raised for the thin wall (1.5 x 2 pi "
                                                     "sqrt(R / t), docs/validation/accuracy-by-level.md, \"Thin walls\")"}));
        CHECK(has_line(t.out, {"[mesh] rule = mesh from the band", "top 250 Hz ([analysis] band), no ring mode"}));
        const Run coarse = run_coremodal(dir, "check thin.toml --mesh coarse");
        CHECK(has_line(coarse.out, {"[mesh] around = 32", "command line (--mesh): its 16 raised for the thin wall"}));
    }
    SECTION("a band that holds higher ring modes raises the count further, and says why") {
        // The same thin core's 20 lowest modes (six rigid): thin-ring n = 2, 3
        // and 4 (about 300, 840, 1620 Hz) among the bending pairs; n = 4 at 1 %
        // asks for 60 around, at `coarse`'s 3 % for 48 (scene/mesh_rule.hpp).
        std::string thin = kBareCore;
        thin.replace(thin.find("wall = \"15 mm\""), std::string("wall = \"15 mm\"").size(), "wall = \"1.52 mm\"");
        dir.write("thin20.toml", thin);
        const Run t = run_coremodal(dir, "check thin20.toml");
        INFO("stdout: " << t.out << "\nstderr: " << t.err);
        REQUIRE(t.exit_code == 0);
        CHECK(has_line(t.out, {"[mesh] around = 60", "from the level: its 32 raised for the band's n = 4"}));
        CHECK(has_line(t.out, {"[mesh] rule = mesh from the band", "(estimated for 20 modes", "highest n = 4",
                               "it asks for 60 around"}));
        const Run coarse = run_coremodal(dir, "check thin20.toml --mesh coarse");
        CHECK(has_line(coarse.out, {"[mesh] around = 48", "command line (--mesh): its 16 raised for the band's n = 4"}));
    }
}

TEST_CASE("coremodal check lists a chuck scene's effects and explains model = auto", "[app][cli][check]") {
    TempDir dir;
    SECTION("case 07: elastic chucks in an elastic stand, a body of revolution") {
        const Run r = run_coremodal(
            dir, "check '" COREMODAL_SOURCE_DIR "/cases/07-rotogravure-chucks-150x15.8-4320.toml' --model auto");
        INFO("stdout: " << r.out);
        REQUIRE(r.exit_code == 0);
        for (const char* effect : {"core", "rest_paper", "elastic_chucks", "contact_compliance", "bearing_springs",
                                   "frame_mass"})
            CHECK(has_line(r.out, {"  " + std::string(effect) + "  "}));
        CHECK(has_line(r.out, {"model level: harmonic (--model auto; a body of revolution"}));
        CHECK(has_line(r.out, {"[supports.left.bearing] frame_mass = 150 kg", "file"}));
    }
    SECTION("case 10: segmented chucks; the right chuck mirrors the left one") {
        const Run r =
            run_coremodal(dir, "check '" COREMODAL_SOURCE_DIR "/cases/10-segmented-chuck-76x15-2200.toml' --model auto");
        INFO("stdout: " << r.out);
        REQUIRE(r.exit_code == 0);
        CHECK(has_line(r.out, {"model level: coupled (--model auto; the left chuck's expanding element at 70 mm has 3 "
                               "segments, which are not axisymmetric; the roll and chucks are bodies of revolution"}));
        CHECK(has_line(r.out, {"[supports.left] body_diameter = 0.075 m", "file: bore - 2 x clearance 0.0005 m"}));
        CHECK(has_line(r.out, {"[supports.right] inserted_length = 0.11 m", "mirrors [supports.left]"}));
        CHECK(has_line(r.out, {"[supports.left] normal_stiffness", "from expansion_pressure = 600 kPa (file)"}));
        CHECK(has_line(r.out, {"[supports.left.bearing] type = \"rigid\"", "default: no [bearing]"}));
    }
}

TEST_CASE("coremodal check describes the forced response's damping, excitation and speeds", "[app][cli][check][response]") {
    TempDir dir;
    const Run r =
        run_coremodal(dir, "check '" + std::string(COREMODAL_SOURCE_DIR) + "/cases/13-rest-roll-response-150x15.8-4320.toml'");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(has_line(r.out, {"forced response (docs/how-to/response.md):"}));
    CHECK(has_line(r.out, {"damping of every mode not named below: [damping] ratio = 0.01"}));
    CHECK(has_line(r.out, {"excitation: bow 0.0005 m (half_sine)", "gravity on"}));
    CHECK(has_line(r.out, {"speeds: 301 rotation speeds from", "(from web speeds at the roll's outer diameter)"}));
    CHECK(has_line(r.out, {"amplitude limit: 0.005 m at mid-span"}));
    // A case without [response] has no such lines.
    dir.write("bare.toml", kBareCore);
    const Run plain = run_coremodal(dir, "check '" + (dir.path / "bare.toml").string() + "'");
    CHECK(plain.exit_code == 0);
    CHECK_FALSE(has_line(plain.out, {"forced response"}));
}
