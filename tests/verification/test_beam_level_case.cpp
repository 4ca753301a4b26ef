// Case 05 (cases/05-beam-level-rest-roll-150x15.8-4320.toml), the beam model
// level of case 03's rest roll, run as a user runs it: results in a folder.
#include "analyses/run/run.hpp"
#include "output/run_writer.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace coremodal;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

size_t lines_of(const std::string& text) { return static_cast<size_t>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

TEST_CASE("Case 05: the rest roll as a beam, written like a solid run", "[cases][beam]") {
    const fs::path out = fs::temp_directory_path() / ("coremodal_case05_" + std::to_string(::getpid()));
    fs::remove_all(out);
    RunOptions options;
    options.case_file = std::string(COREMODAL_SOURCE_DIR) + "/cases/05-beam-level-rest-roll-150x15.8-4320.toml";
    options.quiet = true;
    options.output_dir = out.string();
    options.write = write_run;  // what `coremodal run` writes
    const RunReport r = run_case(options);

    CHECK(r.scene.model == ModelChoice::beam);
    CHECK(r.model.level == ModelChoice::beam);
    CHECK(r.modes.verification.complete);
    CHECK(r.modes.verification.max_relative_residual < 1e-10);
    CHECK(r.model.mass_kg == Approx(r.model.expected_mass_kg).epsilon(1e-12));
    REQUIRE(r.modes.modes.size() == 13);  // 12 asked; the pair at the edge is kept whole
    // The pasted results of the case file.
    CHECK(r.modes.modes[0].frequency_hz == Approx(35.4327).epsilon(1e-5));
    CHECK(r.beam.fe_over_timoshenko == Approx(1).epsilon(1e-5));
    CHECK(r.modes.modes[4].label.type == "torsion");
    CHECK(r.modes.modes[4].frequency_hz == Approx(162.41).epsilon(1e-4));
    CHECK(r.modes.modes[9].label.type == "axial");
    CHECK(r.modes.modes[9].frequency_hz == Approx(310.17).epsilon(1e-4));

    const std::string summary = slurp(out / "summary.json");
    CHECK(summary.find("\"level\": \"beam\"") != std::string::npos);
    CHECK(summary.find("\"model\": \"beam\"") != std::string::npos);
    CHECK(lines_of(slurp(out / "modes.csv")) == 1 + 13);
    const std::string shapes = slurp(out / "beam_shapes.csv");
    CHECK(shapes.rfind("mode,node,beam,z_m,ux,uy,uz,rx,ry,rz\n", 0) == 0);
    CHECK(lines_of(shapes) == 1 + 13 * static_cast<size_t>(r.model.n_nodes));
    CHECK_FALSE(fs::exists(out / "modes.h5"));  // the beam level writes no mesh results
    fs::remove_all(out);
}

TEST_CASE("The beam level on chucks reports the chuck factor with f2 from the beam of the free span",
          "[cases][beam][chucks]") {
    RunOptions options;
    options.case_file = std::string(COREMODAL_SOURCE_DIR) + "/bench/beam_rest_roll_chucks.toml";
    options.quiet = true;
    options.write_results = false;
    const RunReport r = run_case(options);
    REQUIRE(r.model.level == ModelChoice::beam);
    REQUIRE(r.chuck);
    const ChuckFactor& k = *r.chuck;
    // Li = 250 mm at both ends (the chuck mirrors): L = 4.32 - 2 x 0.25 = 3.82 m.
    CHECK(k.li_m == Approx(0.25));
    CHECK(k.free_span_m == Approx(3.82));
    CHECK(k.f1_hz == Approx(r.beam.fe_first_bending_hz));
    // The free-free beam network of the span is the Timoshenko beam the
    // closed form solves: they differ by the network's discretisation only
    // (30 elements, error ~h^4: measured 3e-6 for the first bending mode).
    CHECK(k.f2_fe_hz == Approx(k.f2_beam_hz).epsilon(1e-5));
    // A soft stand (bearings, frames) holds the roll below the free span's
    // free-free frequency: 0 < k < 1 (Ilomäki I-6).
    CHECK(k.chuck_factor > 0);
    CHECK(k.chuck_factor < 1);
    CHECK(k.chuck_factor == Approx(k.f1_hz / k.f2_fe_hz));
}
