// `coremodal fit` and `coremodal sensitivity` as a user runs them: the files,
// the output-folder rule, errors with file:line that write nothing.
#include "support/tiny_case.hpp"
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

using namespace coremodal::testing;
namespace fs = std::filesystem;

namespace {

const std::string kIso = coremodal::testing::iso_sample_case("beam", 14);

// Three free-free bending modes of a 76x15 sample, 1.5 m.
const char* kMeasurements = R"(parameters = ["core.material.E_z", "core.material.G_thetaz"]
[[measurement]]
case = "iso.toml"
mode = "bending n=1 m=2"
frequency = "133.2 Hz"
uncertainty = "0.3 Hz"
[[measurement]]
case = "iso.toml"
mode = "bending n=1 m=3"
frequency = "340 Hz"
[[measurement]]
case = "iso.toml"
mode = "bending n=1 m=4"
frequency = "600 Hz"
)";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("fit writes fit.toml, report.md and a calibrated case that runs", "[fit][app]") {
    TempDir dir("fit");
    dir.write("iso.toml", kIso);
    dir.write("m.toml", kMeasurements);
    const Run r = run_coremodal(dir, "fit m.toml -o out -q");
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(contains(slurp(dir.path / "out" / "fit.toml"), "key = \"core.material.G_thetaz\""));
    const std::string report = slurp(dir.path / "out" / "report.md");
    CHECK(contains(report, "## Correlations"));
    // Two measurements give no uncertainty: the report says which value it assumed.
    size_t assumed = 0;
    for (size_t at = report.find("(assumed: 1 %, none given)"); at != std::string::npos;
         at = report.find("(assumed: 1 %, none given)", at + 1))
        ++assumed;
    CHECK(assumed == 2);
    const Run again = run_coremodal(dir, "run out/iso-fitted.toml -o run -q --no-plots");
    INFO(again.err);
    CHECK(again.exit_code == 0);
}

TEST_CASE("fit and sensitivity refuse the user's folder before any work, and name bad input", "[fit][app]") {
    TempDir dir("fit");
    dir.write("iso.toml", kIso);
    dir.write("m.toml", kMeasurements);
    fs::create_directories(dir.path / "mine");
    dir.write("mine/keep.txt", "mine");
    for (const std::string command : {"fit m.toml", "sensitivity iso.toml"}) {
        INFO(command);
        const Run r = run_coremodal(dir, command + " --output mine");
        CHECK(r.exit_code == 1);
        CHECK(contains(r.err, "exists and was not written by coremodal"));
        CHECK(r.out.empty());
        CHECK(slurp(dir.path / "mine" / "keep.txt") == "mine");
    }
    dir.write("bad.toml", std::string(kMeasurements) + "[[measurement]]\ncase = \"iso.toml\"\nmode = \"bending\"\n"
                                                       "frequency = \"1 Hz\"\n");
    const Run bad = run_coremodal(dir, "fit bad.toml -o out");
    CHECK(bad.exit_code != 0);
    CHECK(contains(bad.err, "bad.toml:17:8"));
    const Run key = run_coremodal(dir, "sensitivity iso.toml -p core.material.G_zz -o out");
    CHECK(key.exit_code != 0);
    CHECK(contains(key.err, "G_zz"));
    CHECK_FALSE(fs::exists(dir.path / "out"));
}
