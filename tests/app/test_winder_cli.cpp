// `coremodal winder` as a user meets it: the real binary on a small winder
// file in a temporary folder; bad input refused with its place and nothing
// written.
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

bool written(const fs::path& p) { return fs::is_regular_file(p) && fs::file_size(p) > 0; }

// The paper's example winder on a short sweep.
const std::string kSmallWinder = R"(name = "small"
[winder]
web_speed = "2000 m/min"
[winder.sweep]
points = 6
)";

}  // namespace

TEST_CASE("coremodal winder writes its tables, pictures and report", "[app][winder]") {
    TempDir dir("winder");
    dir.write("small.toml", kSmallWinder);
    const Run r = run_coremodal(dir, "winder small.toml --output out");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("winder: 6 roll diameters from 400 mm to 1800 mm") != std::string::npos);
    CHECK(r.out.find("crosses a drum mode") != std::string::npos);
    // Not a terminal (stderr is a file here): progress as whole lines, never silent, never "\r".
    CHECK(r.err.find("winder: diameter 1 of 6\n") != std::string::npos);
    CHECK(r.err.find("winder: diameter 6 of 6\n") != std::string::npos);
    CHECK(r.err.find('\r') == std::string::npos);
    for (const char* f : {"winder.csv", "crossings.csv", "response.csv", "summary.json", "report.md",
                          "crossing_diagram.png", "response.png"})
        CHECK(written(dir.path / "out" / f));
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(report.find("not the paper's eq. 9") != std::string::npos);
    CHECK(report.find("at 6 of 6 diameters") != std::string::npos);  // none missed anywhere
    CHECK(report.find("`[winder.drums] gap = 0.1 m (assumed)`") != std::string::npos);
    const std::string csv = slurp(dir.path / "out" / "winder.csv");
    CHECK(csv.rfind("roll_diameter_m,mode,frequency_hz,type,track,", 0) == 0);
}

TEST_CASE("coremodal winder refuses bad input, naming the place, and writes nothing", "[app][winder]") {
    TempDir dir("winder_bad");
    dir.write("bad.toml", "[winder]\n[winder.rolls]\ncount = 0\n");
    const Run r = run_coremodal(dir, "winder bad.toml --output out --no-plots");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("bad.toml:3:9: [winder.rolls] count = 0: out of range") != std::string::npos);
    CHECK(!fs::exists(dir.path / "out"));
}
