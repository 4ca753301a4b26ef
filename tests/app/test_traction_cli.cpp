// `coremodal traction` as a user meets it: the real binary on the shipped
// case 19 and on small files in a temporary folder; bad input refused with
// its place, exit 1 and nothing written.
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

bool written(const fs::path& p) { return fs::is_regular_file(p) && fs::file_size(p) > 0; }

const std::string kCase16 = std::string(COREMODAL_SOURCE_DIR) + "/cases/19-grooved-idler-traction.toml";

// Roller 2 of Rice & Gans (plain) at 44 N/m, the default speeds.
const std::string kPlain = R"(name = "plain"
[traction]
roller_radius = "50 mm"
wrap = "90 deg"
tension = "44 N/m"
friction = 0.55
roller_roughness = "25.9 um"
web_roughness = 0
web_thickness = "180 um"
web_density = "1358 kg/m^3"
)";

}  // namespace

TEST_CASE("coremodal traction writes its table, summary, picture and report", "[app][traction]") {
    TempDir dir("traction");
    const Run r = run_coremodal(dir, "traction '" + kCase16 + "' --output out");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("zero-traction speed 25.1 m/s") != std::string::npos);
    CHECK(r.out.find("slips under 20 N/m at 19.8 m/s") != std::string::npos);
    CHECK(r.err.find("warning: 1 of 61 web speeds are outside Rice & Gans' validity limits, the first at 25 m/s: "
                     "theta* = 0.121") != std::string::npos);
    for (const char* f : {"traction.csv", "summary.json", "report.md", "traction.png"}) CHECK(written(dir.path / "out" / f));
    const std::string csv = slurp(dir.path / "out" / "traction.csv");
    CHECK(csv.rfind("web_speed_m_s,tension_N_m,air_pressure_Pa,", 0) == 0);
    CHECK(csv.find("plain_traction_N_m") != std::string::npos);
    const std::string report = slurp(dir.path / "out" / "report.md");
    // theta* passes 0.1 at 25 m/s, just short of the zero-traction speed (case 19 says why).
    CHECK(report.find("**1 of 61 points are outside the paper's limits**; the first: theta* = 0.121 >= 0.1") !=
          std::string::npos);
    CHECK(report.find("![traction.png](traction.png)") != std::string::npos);
    const std::string summary = slurp(dir.path / "out" / "summary.json");
    CHECK(summary.find("\"zero_traction_m_s\"") != std::string::npos);
    CHECK(summary.find("\"groove_speed_gain\"") != std::string::npos);
}

TEST_CASE("coremodal traction on a plain roller takes the default speeds and says so", "[app][traction]") {
    TempDir dir("traction_plain");
    dir.write("plain.toml", kPlain);
    const Run r = run_coremodal(dir, "traction plain.toml --output out --no-plots");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("zero-traction speed 4.18 m/s") != std::string::npos);  // the paper: "around 4.1 m/s"
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(report.find("(No picture: switched off (--no-plots).)") != std::string::npos);
    CHECK(report.find("51 speeds from 0 to 5.23 m/s") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out" / "traction.png"));
}

TEST_CASE("coremodal traction refuses bad input, naming the place, and writes nothing", "[app][traction]") {
    TempDir dir("traction_bad");
    std::string bad = kPlain;
    bad.replace(bad.find("wrap = \"90 deg\""), 15, "wrap = \"-5 deg\"");
    dir.write("bad.toml", bad);
    Run r = run_coremodal(dir, "traction bad.toml --output out --no-plots");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("bad.toml:4:8: [traction] wrap = -0.0872665 rad must be positive") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out"));

    dir.write("none.toml", "name = \"x\"\n");
    r = run_coremodal(dir, "traction none.toml --output out --no-plots");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("none.toml: no [traction] table") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out"));

    SECTION("check says the same file is valid and what it resolves to") {
        dir.write("plain.toml", kPlain);
        const Run c = run_coremodal(dir, "check plain.toml");
        CHECK(c.exit_code == 0);
        CHECK(c.out.find("plain.toml: valid traction file \"plain\"") != std::string::npos);
        CHECK(c.out.find("zero-traction speed 4.18 m/s") != std::string::npos);
    }
}
