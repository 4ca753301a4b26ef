// report.md of a run, from a RunReport built by hand: which modes get a
// picture, what the report says for a free scene and without pictures, and
// the python runner's answer when the interpreter does not exist.
#include "output/python_plots.hpp"
#include "output/run_markdown.hpp"
#include "output/run_pictures.hpp"

#include "support/test_modes.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

using namespace coremodal;
using coremodal::testing::mode;

namespace {

RunReport free_tube() {
    RunReport r;
    r.scene.name = "hand-made";
    r.scene.source_file = "hand.toml";
    r.scene.core = {0.076, 0.106, 1.0, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850)};
    r.model.mass_kg = 10;
    r.model.expected_mass_kg = 10;
    r.modes.modes = {mode(1, 0.001, "rigid"), mode(2, 200, "bending"), mode(3, 200, "bending"),
                     mode(4, 450, "ovalling", 2), mode(5, 900, "torsion", 0)};
    r.beam.ends = "free-free";
    r.beam.fe_first_bending_hz = 200;
    r.beam.fe_mode_index = 2;
    r.beam.euler_bernoulli_hz = 210;
    r.beam.timoshenko_hz = 205;
    r.beam.fe_over_euler_bernoulli = 200.0 / 210;
    r.beam.fe_over_timoshenko = 200.0 / 205;
    return r;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("The report pictures the lowest mode of each type, never a rigid mode or a pair's partner",
          "[output][report]") {
    const RunReport r = free_tube();
    CHECK(modes_to_picture(r.modes.modes) == std::vector<int>{2, 4, 5});
    CHECK(modes_to_picture(r.modes.modes, 2) == std::vector<int>{2, 4});
    CHECK(mode_picture_file(7) == "mode_07.png");
    CHECK(mode_picture_file(12) == "mode_12.png");
}

TEST_CASE("A free scene's report gives no speeds and says why there are no pictures", "[output][report]") {
    RunReport r = free_tube();
    r.warnings.push_back("part 'chuck_left' is not held");
    RunPictures none;
    none.problem = "switched off (--no-plots)";
    const std::string md = run_report_markdown(r, none);
    CHECK(contains(md, "# hand-made\n"));
    CHECK(contains(md, "| core | ID 76 mm × wall 15 mm × length 1 m"));
    CHECK(contains(md, "| rest paper | none (bare core)"));
    CHECK(contains(md, "| supports | free"));
    CHECK(contains(md, "| 4 | 450.0000 | ovalling | 2 | 0 |"));
    CHECK_FALSE(contains(md, "eff. mass"));  // no effective masses in this report
    CHECK(contains(md, "| Euler–Bernoulli (I-7, k = 1) | 210.0000 | 0.9524 |"));
    CHECK(contains(md, "Not given: the scene is free–free"));
    CHECK_FALSE(contains(md, "## Chuck factor"));
    CHECK(contains(md, "No pictures: switched off (--no-plots)."));
    CHECK(contains(md, "## Warnings\n\n- part 'chuck_left' is not held\n"));
}

TEST_CASE("The run report opens with the answers: f1, the speeds and the mode count", "[output][report]") {
    RunReport r = free_tube();
    r.modes.verification.complete = true;
    const std::string md = run_report_markdown(r, RunPictures{});
    // The first table of the report (report.html shows it first) is the summary.
    CHECK(md.find("| result | value |") < md.find("| part | dimensions | material |"));
    CHECK(contains(md, "| first bending frequency f1 (FE) | 200.0000 Hz |"));
    CHECK(contains(md, "| safe web speed | not given: the scene is free–free"));
    CHECK(contains(md, "| modes found | 5, none missed (see Model and verification) |"));
    r.modes.verification.complete = false;
    CHECK(contains(run_report_markdown(r, RunPictures{}), "| modes found | 5, INCOMPLETE"));
}

TEST_CASE("The report embeds the pictures it is given and lists the rigid comparison", "[output][report]") {
    RunReport r = free_tube();
    r.rigid_comparison = {{"bending", 1, 0, 2, 3, 190.0, 200.0}, {"torsion", 0, 0, 5, 0, 900.0, 0.0}};
    RunPictures p;
    p.spectrum = "spectrum.png";
    p.modes = {{2, "mode_02.png"}, {4, "mode_04.png"}};
    const std::string md = run_report_markdown(r, p);
    CHECK(contains(md, "![frequencies by mode type](spectrum.png)"));
    CHECK(contains(md, "![mode 4](mode_04.png)"));
    CHECK(contains(md, "| bending | 1 | 0 | 2 | 190.0000 | 3 | 200.0000 | -5.00 % |"));
    CHECK(contains(md, "| torsion | 0 | 0 | 5 | 900.0000 | - | - | - |"));
}

TEST_CASE("A python that cannot start is a reason, not an exception", "[output][report]") {
    const char* before = std::getenv("COREMODAL_PYTHON");
    const std::string saved = before ? before : "";
    ::setenv("COREMODAL_PYTHON", "/nonexistent/python3", 1);
    const auto dir = std::filesystem::temp_directory_path() / "coremodal_test_python_plots";
    std::filesystem::create_directories(dir);
    const std::string why = run_python_plot("run-plot", dir, {"--modes", "1"});
    if (before) ::setenv("COREMODAL_PYTHON", saved.c_str(), 1);
    else ::unsetenv("COREMODAL_PYTHON");
    CHECK(why == "/nonexistent/python3 -m coremodal run-plot could not start: No such file or directory");
    CHECK_FALSE(std::filesystem::exists(dir / "plot.log"));
    std::filesystem::remove_all(dir);
}
