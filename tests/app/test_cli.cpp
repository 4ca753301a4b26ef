// The program as a user meets it: the real coremodal binary run on small case
// files written to a temporary folder. Bad input must stop it with a located
// message on stderr and leave no results behind; good input must produce the
// whole results folder, serially and under mpirun.
#include "support/program_run.hpp"
#include "support/tiny_case.hpp"

#include "support/json_lookup.hpp"  // json_number: read back summary.json

#include <catch2/catch.hpp>

#include <algorithm>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

// Anything a run left in dir besides the case and mesh files it was given.
std::vector<std::string> leftovers(const TempDir& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.path)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory() || name.find(".partial-") != std::string::npos) names.push_back(name);
    }
    return names;
}

const std::string kCoreHeader = R"(name = "bad"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "0.5 m"
)";

struct BadCase {
    std::string what;
    std::string toml;
    std::vector<std::string> expected;  // all must appear on stderr
};

std::vector<BadCase> bad_cases() {
    const std::string tet10 = std::string(COREMODAL_SOURCE_DIR) + "/meshes/tube-76x15-tet10.msh";
    return {
        {"inner diameter not below the outer one",
         "name = \"bad\"\n\n[core]\ninner_diameter = \"120 mm\"\nouter_diameter = \"106 mm\"\nlength = \"0.5 m\"\n",
         {"bad.toml:4:", "inner_diameter", "outer_diameter"}},
        {"a negative modulus",
         kCoreHeader + "material = { E = \"-210 GPa\", nu = 0.3, density = \"7850 kg/m^3\" }\n",
         {"bad.toml:7:", "E = -210 GPa", "positive"}},
        {"Poisson ratios that make the compliance indefinite",
         kCoreHeader + "material = { base = \"paperboard_core\", nu_rtheta = 0.9, nu_rz = 0.9, nu_thetaz = 0.9 }\n",
         {"bad.toml:7:", "material", "positive definite"}},
        {"an unknown key",
         "name = \"bad\"\n\n[core]\ninner_diameter = \"76 mm\"\nouter_diamter = \"106 mm\"\nlength = \"0.5 m\"\n",
         {"bad.toml:5:", "outer_diamter", "did you mean 'outer_diameter'"}},
        {"a mass for a diameter",
         "name = \"bad\"\n\n[core]\ninner_diameter = \"76 kg\"\nwall = \"15 mm\"\nlength = \"0.5 m\"\n",
         {"bad.toml:4:", "inner_diameter", "76 kg", "mass", "length"}},
        {"overlapping clamp zones",
         kCoreHeader + "\n[supports]\ntype = \"clamped\"\n\n[supports.left]\nlength = \"300 mm\"\n",
         {"bad.toml:12:", "[supports.left]", "[supports.right]", "overlap"}},
        {"a clamp zone longer than the core",
         kCoreHeader + "\n[supports]\ntype = \"clamped\"\n\n[supports.left]\nlength = \"2 m\"\n",
         {"bad.toml:12:", "[supports.left]", "[core] length"}},
        {"more modes than the mesh has DOFs",
         kCoreHeader + "\n[analysis]\nmodes = 10000\n\n[mesh]\naround = 8\nalong = 2\nthrough_wall = 1\n",
         // Found only after meshing: the scene keeps no line numbers, so the
         // message names the file and the key, not the line.
         {"bad.toml", "[analysis] modes = 10000", "degrees of freedom"}},
        {"a missing mesh file",
         kCoreHeader + "\n[mesh]\nfile = \"nothere.msh\"\n",
         {"bad.toml:9:", "[mesh] file", "nothere.msh"}},
        {"a mesh file that is not a mesh",
         kCoreHeader + "\n[mesh]\nfile = \"garbage.msh\"\n",
         {"garbage.msh"}},
        {"a mesh without the clamp groups the supports need",
         "name = \"bad\"\n\n[core]\ninner_diameter = \"76 mm\"\nwall = \"15 mm\"\nlength = \"1 m\"\n\n"
         "[supports]\ntype = \"clamped\"\n\n[supports.left]\nlength = \"70 mm\"\n\n[mesh]\nfile = \"" +
             tet10 + "\"\n",
         {tet10, "clamp_left", "[supports] type = \"clamped\"", "'core_inner', 'core_outer'"}},
    };
}

// (frequency, type) of every row of modes.csv: index,frequency_hz,type,...
std::vector<std::pair<double, std::string>> csv_modes(const fs::path& csv) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);  // header
    std::vector<std::pair<double, std::string>> modes;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::string index, freq, type;
        std::getline(row, index, ',');
        std::getline(row, freq, ',');
        std::getline(row, type, ',');
        modes.emplace_back(std::stod(freq), type);
    }
    return modes;
}

// The type column of modes.csv, every row.
std::vector<std::string> mode_types(const fs::path& csv) {
    std::vector<std::string> types;
    for (const auto& [f, type] : csv_modes(csv)) types.push_back(type);
    return types;
}

// Elastic frequencies (Hz) from modes.csv. Rigid modes are left out: their
// frequencies are round-off (~1e-3 Hz).
std::vector<double> elastic_frequencies(const fs::path& csv) {
    std::vector<double> f;
    for (const auto& [hz, type] : csv_modes(csv))
        if (type != "rigid") f.push_back(hz);
    return f;
}

}  // namespace

TEST_CASE("Every kind of bad input stops coremodal with a located message and no results", "[app][cli]") {
    for (const auto& bad : bad_cases()) {
        DYNAMIC_SECTION("bad input: " << bad.what) {
            TempDir dir;
            dir.write("bad.toml", bad.toml);
            dir.write("garbage.msh", "this is not a mesh\n$Nodes\nnonsense\n");
            const Run r = run_coremodal(dir, "run bad.toml -o results -q");
            INFO("stderr: " << r.err);
            CHECK(r.exit_code != 0);
            CHECK(r.err.find("error") != std::string::npos);
            for (const auto& text : bad.expected) {
                INFO("expected on stderr: " << text);
                CHECK(r.err.find(text) != std::string::npos);
            }
            CHECK(leftovers(dir).empty());
        }
    }
}

TEST_CASE("A missing case file is an error naming it", "[app][cli]") {
    TempDir dir;
    const Run r = run_coremodal(dir, "run nothere.toml -o results -q");
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("nothere.toml") != std::string::npos);
    CHECK(leftovers(dir).empty());
}

TEST_CASE("A good tiny case writes the whole results folder", "[app][cli]") {
    TempDir dir;
    dir.write("tiny.toml", kTinyCase);
    const Run r = run_coremodal(dir, "run tiny.toml -o results -q --no-plots");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    // One line only: 8 around is far coarser than the band's n = 2 ovalling
    // needs (scene/mesh_rule.hpp; it pushes that pair out of the 12 modes).
    CHECK_THAT(r.err, Catch::StartsWith("coremodal: warning: tiny.toml: [mesh] is coarser than the band needs"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    for (const char* file : {"summary.json", "modes.csv", "modes.h5", "modes.xdmf", "report.md"}) {
        INFO(file);
        CHECK(fs::is_regular_file(dir.path / "results" / file));
        CHECK(fs::file_size(dir.path / "results" / file) > 0);
    }
    // 12 modes: 6 rigid + 6 elastic.
    CHECK(elastic_frequencies(dir.path / "results" / "modes.csv").size() == 6);
    // A free body of few unknowns: no one factor at a predicted edge, so no
    // factor precision to report (absent, not a made-up value; issue 39).
    CHECK_FALSE(coremodal::json_at(slurp(dir.path / "results" / "summary.json"), "verification.factor_precision")
                    .has_value());
    CHECK(leftovers(dir) == std::vector<std::string>{"results"});
}

TEST_CASE("The help texts exit cleanly and name the options", "[app][cli]") {
    TempDir dir;
    SECTION("coremodal --help") {
        const Run r = run_coremodal(dir, "--help");
        CHECK(r.exit_code == 0);
        CHECK(r.out.find("run") != std::string::npos);
    }
    SECTION("coremodal run --help") {
        const Run r = run_coremodal(dir, "run --help");
        CHECK(r.exit_code == 0);
        CHECK(r.out.find("--output") != std::string::npos);
        CHECK(r.out.find("--quiet") != std::string::npos);
        CHECK(r.out.find("PETSc") != std::string::npos);
    }
    SECTION("no subcommand is an error") {
        const Run r = run_coremodal(dir, "");
        CHECK(r.exit_code != 0);
    }
}

TEST_CASE("PETSc and SLEPc options pass through to the solver", "[app][cli]") {
    TempDir dir;
    dir.write("tiny.toml", kTinyCase);
    // -eps_view prints SLEPc's description of the solver on stdout; -eps_tol
    // overrides the case's tolerance (1e-10 by default) and shows up in it.
    const Run r = run_coremodal(dir, "run tiny.toml -o results -q --no-plots -eps_tol 1e-9 -eps_view");
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("EPS Object") != std::string::npos);
    CHECK(r.out.find("krylovschur") != std::string::npos);
    CHECK(r.out.find("tolerance: 1e-09") != std::string::npos);
}

TEST_CASE("Two MPI ranks give the serial frequencies, at the solid and the harmonic level", "[app][cli][mpi][hard]") {
    // Hard case 09: the scene is cases/hard/09-parallel.toml.
    const std::string case_file = "'" COREMODAL_SOURCE_DIR "/cases/hard/09-parallel.toml'";
    for (const std::string model : {"solid", "harmonic"}) {
        INFO("--model " << model);
        TempDir dir;
        const std::string args = " -q --no-plots --model " + model;
        const Run serial = run_coremodal(dir, "run " + case_file + " -o serial" + args);
        INFO("serial stdout: " << serial.out << "\nstderr: " << serial.err);
        REQUIRE(serial.exit_code == 0);
        const Run parallel = run_coremodal(
            dir, "run " + case_file + " -o parallel" + args,
            "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 2 --oversubscribe ");
        INFO("mpirun stdout: " << parallel.out << "\nstderr: " << parallel.err);
        REQUIRE(parallel.exit_code == 0);
        const auto f1 = elastic_frequencies(dir.path / "serial" / "modes.csv");
        const auto f2 = elastic_frequencies(dir.path / "parallel" / "modes.csv");
        // 12 modes asked: 6 rigid and 6 elastic; the harmonic level completes
        // its 12th mode is the first of a pair, and a pair is never cut in half.
        REQUIRE(f1.size() == (model == "solid" ? 6u : 7u));
        REQUIRE(f2.size() == f1.size());
        // The same matrices in a different partition: MUMPS's pivoting order and
        // the Krylov basis differ, so the eigenvalues agree to the solver's
        // residual (1e-10 relative in lambda), not bitwise; 1e-8 in f leaves room.
        for (size_t i = 0; i < f1.size(); ++i) CHECK(f2[i] == Approx(f1[i]).epsilon(1e-8));
        // Both runs proved complete (inertia count) and verified to 1e-8, and
        // name the modes alike.
        for (const char* run : {"serial", "parallel"}) {
            INFO(run);
            const std::string summary = slurp(dir.path / run / "summary.json");
            CHECK(summary.find("\"complete\": true") != std::string::npos);
            CHECK(summary.find("\"level\": \"" + std::string(model) + "\"") !=
                  std::string::npos);
            CHECK(coremodal::json_number(summary, "verification.max_relative_residual").value_or(1) <= 1e-8);
            CHECK(coremodal::json_number(summary, "verification.max_orthonormality_error").value_or(1) <= 1e-8);
        }
        CHECK(mode_types(dir.path / "parallel" / "modes.csv") == mode_types(dir.path / "serial" / "modes.csv"));
        const std::string summary = slurp(dir.path / "parallel" / "summary.json");
        CHECK(summary.find("\"mpi_ranks\": 2") != std::string::npos);
    }
}

namespace {

// Case 03's coarse solid mesh (24,960 unknowns: above the block method's
// floor of 20,000, so the one LDL^T factor at the predicted edge and block
// Lanczos), run into `folder`; stops the test with the output if it fails.
Run case03_coarse_solid(const TempDir& dir, const std::string& folder, const std::string& extra = "",
                        const std::string& launcher = "") {
    const Run r = run_coremodal(dir,
                                "run '" COREMODAL_SOURCE_DIR "/cases/03-rest-roll-150x15.8-4320.toml' -o " + folder +
                                    " --no-plots --model solid --mesh coarse" + extra,
                                launcher);
    if (r.exit_code != 0) FAIL(folder << " failed; stdout: " << r.out << "\nstderr: " << r.err);
    return r;
}

}  // namespace

TEST_CASE("Two MPI ranks solve in blocks on MUMPS's distributed factor and give the serial frequencies",
          "[app][cli][mpi]") {
    // The parallel run sums its inner products over the ranks and numbers
    // the nodes in slabs.
    TempDir dir;
    const Run serial = case03_coarse_solid(dir, "serial");
    const Run parallel = case03_coarse_solid(
        dir, "parallel", "", "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 2 --oversubscribe ");
    for (const Run* r : {&serial, &parallel}) {
        INFO(r->out);
        CHECK(r->out.find("block Lanczos:") != std::string::npos);
        CHECK(r->out.find("13 negative pivots below") != std::string::npos);
        CHECK(r->out.find(": complete") != std::string::npos);
    }
    const auto f1 = elastic_frequencies(dir.path / "serial" / "modes.csv");
    const auto f2 = elastic_frequencies(dir.path / "parallel" / "modes.csv");
    REQUIRE(f1.size() == 13u);
    REQUIRE(f2.size() == f1.size());
    // Another partition and random start: the pairs agree to the solver's
    // tolerance (1e-10 relative in lambda), 1e-8 in f leaves room.
    for (size_t i = 0; i < f1.size(); ++i) CHECK(f2[i] == Approx(f1[i]).epsilon(1e-8));
    CHECK(mode_types(dir.path / "parallel" / "modes.csv") == mode_types(dir.path / "serial" / "modes.csv"));
    const std::string summary = slurp(dir.path / "parallel" / "summary.json");
    CHECK(coremodal::json_number(summary, "verification.max_relative_residual").value_or(1) <= 1e-8);
    CHECK(coremodal::json_number(summary, "verification.max_orthonormality_error").value_or(1) <= 1e-8);
}

// Issue 39: the single-precision factor (its passes refined to 1e-9, the
// pairs cleaned by Rayleigh-Ritz in double) gives the double factor's
// frequencies to 1e-9 relative (modes.csv's 10 digits resolve ~1e-10), with
// residuals, M-orthonormality and the count as the double run's.
TEST_CASE("Case 03's coarse solid on the single factor gives the double factor's modes to 1e-9",
          "[app][cli][single_factor][long]") {
    TempDir dir;
    const Run dbl = case03_coarse_solid(dir, "double", " -factor_precision double");
    const Run sgl = case03_coarse_solid(dir, "single", " -factor_precision single");
    INFO(sgl.out);
    CHECK(sgl.out.find("Rayleigh-Ritz step(s) with the double K and M") != std::string::npos);
    CHECK(sgl.out.find("count from the single-precision factor's inertia, proven") != std::string::npos);
    for (const Run* r : {&dbl, &sgl}) {
        CHECK(r->out.find("13 negative pivots below") != std::string::npos);
        CHECK(r->out.find(": complete") != std::string::npos);
    }
    const auto f_double = elastic_frequencies(dir.path / "double" / "modes.csv");
    const auto f_single = elastic_frequencies(dir.path / "single" / "modes.csv");
    REQUIRE(f_double.size() == 13u);
    REQUIRE(f_single.size() == f_double.size());
    for (size_t i = 0; i < f_double.size(); ++i) CHECK(f_single[i] == Approx(f_double[i]).epsilon(1e-9));
    const std::string summary = slurp(dir.path / "single" / "summary.json");
    CHECK(coremodal::json_number(summary, "verification.max_relative_residual").value_or(1) <= 1e-10);
    CHECK(coremodal::json_number(summary, "verification.max_orthonormality_error").value_or(1) <= 1e-12);
    // The run says which precision it used, what was asked and where its
    // count came from: summary.json, the console after the verification
    // line, report.md (issue 39).
    for (const char* precision : {"single", "double"}) {
        INFO(precision);
        const std::string s = slurp(dir.path / precision / "summary.json");
        CHECK(coremodal::json_string(s, "verification.factor_precision.used") == precision);
        CHECK(coremodal::json_string(s, "verification.factor_precision.asked") == precision);
        CHECK(coremodal::json_string(s, "verification.factor_precision.why").value_or("").find(
                  std::string("as -factor_precision ") + precision + " asks") != std::string::npos);
        const std::string report = slurp(dir.path / precision / "report.md");
        CHECK(report.find(std::string("- factor of K − σM: **") + precision + " precision**") != std::string::npos);
    }
    CHECK_THAT(coremodal::json_string(summary, "verification.factor_precision.count").value_or(""),
               Catch::StartsWith("the single-precision factor's inertia, proven: no eigenvalue of K - sigma M within"));
    CHECK(coremodal::json_string(slurp(dir.path / "double" / "summary.json"), "verification.factor_precision.count") ==
          "the double-precision factor's inertia");
    CHECK(sgl.out.find("factor of K - sigma M: single precision (-factor_precision single: ") != std::string::npos);
    CHECK(dbl.out.find("factor of K - sigma M: double precision (-factor_precision double: ") != std::string::npos);
}

TEST_CASE("A factor larger than the memory allowed goes to disk on its own and gives the frequencies of one in memory",
          "[app][cli]") {
    // -max_memory_mb 1 caps the memory the run may take below MUMPS's
    // estimate for the one LDL^T factor: coremodal keeps it out of core
    // (what a machine or a batch job short of memory gets), says so with the
    // estimate, and a user's -mat_mumps_icntl_22 0 still decides.
    TempDir dir;
    const Run in_core = case03_coarse_solid(dir, "in_core");
    const Run on_disk = case03_coarse_solid(dir, "on_disk", " -max_memory_mb 1");
    const Run users_choice = case03_coarse_solid(dir, "users_choice", " -max_memory_mb 1 -mat_mumps_icntl_22 0");
    INFO("out of core: " << on_disk.out);
    CHECK(in_core.out.find("kept on disk") == std::string::npos);
    CHECK(users_choice.out.find("kept on disk") == std::string::npos);
    CHECK(on_disk.out.find("the factor is kept on disk") != std::string::npos);
    CHECK(on_disk.out.find(" MB, more than 60 % of the memory the run may take") != std::string::npos);
    CHECK(on_disk.out.find("block Lanczos:") != std::string::npos);
    CHECK(on_disk.out.find(": complete") != std::string::npos);
    const auto f1 = elastic_frequencies(dir.path / "in_core" / "modes.csv");
    const auto f2 = elastic_frequencies(dir.path / "on_disk" / "modes.csv");
    REQUIRE(f1.size() == 13u);
    REQUIRE(f2.size() == f1.size());
    // The same factor, read back from disk: the same pairs to the solver's
    // tolerance (the solve's order of operations may differ).
    for (size_t i = 0; i < f1.size(); ++i) CHECK(f2[i] == Approx(f1[i]).epsilon(1e-8));
    // A cap that is not a positive size is refused, with what is expected,
    // and no results folder.
    const Run zero = run_coremodal(dir, "run '" COREMODAL_SOURCE_DIR "/cases/03-rest-roll-150x15.8-4320.toml' -o zero"
                                        " --no-plots --model solid --mesh coarse -max_memory_mb 0");
    CHECK(zero.exit_code != 0);
    CHECK(zero.err.find("-max_memory_mb") != std::string::npos);
    CHECK(zero.err.find("a positive number of MB") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "zero"));
}

TEST_CASE("run --model harmonic overrides the case's level; an unknown level is refused", "[app][cli][harmonic]") {
    TempDir dir;
    const std::string case_file = "'" COREMODAL_SOURCE_DIR "/cases/02-clamped-76x15.toml'";
    const Run r = run_coremodal(dir, "run " + case_file + " -o out -q --no-plots --model harmonic");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    const std::string summary = slurp(dir.path / "out" / "summary.json");
    CHECK(summary.find("\"level\": \"harmonic\"") != std::string::npos);
    CHECK(summary.find("\"harmonics\": \"n=0:") != std::string::npos);
    CHECK(std::filesystem::exists(dir.path / "out" / "modes.xdmf"));
    // Case 02's default mesh: the solid's f1 is 61.4408 Hz; the harmonic level, exact around, 61.4433 Hz.
    CHECK(coremodal::json_number(summary, "beam.fe_first_bending_hz").value_or(0) == Approx(61.44).epsilon(1e-3));
    const Run bad = run_coremodal(dir, "run " + case_file + " -o bad -q --model shell");
    CHECK(bad.exit_code != 0);
    CHECK_THAT(bad.err, Catch::Contains("harmonic"));
    CHECK_FALSE(std::filesystem::exists(dir.path / "bad"));
}

// PETSc's own memory checks on a real run: -malloc_debug traces every
// PetscMalloc and -malloc_dump lists, at PetscFinalize, what was never freed
// (both work in Debian's optimized PETSc; -malloc_test and -objects_dump need
// a debug build of PETSc). A Mat, Vec, KSP or EPS that coremodal forgets to
// destroy shows up here, where AddressSanitizer's leak check cannot see it
// (scripts/lsan.supp leaves PETSc's allocations to this test).
TEST_CASE("PETSc's -malloc_dump finds nothing unfreed after a run at the solid and the harmonic level", "[app][cli]") {
    TempDir dir;
    dir.write("tiny.toml", kTinyCase);
    for (const std::string model : {"solid", "harmonic"}) {
        INFO("--model " << model);
        const Run r = run_coremodal(dir, "run tiny.toml -q --no-plots -o out-" + model + " --model " + model +
                                             " -malloc_debug -malloc_dump");
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        CHECK(r.exit_code == 0);
        // Each unfreed block is a line "[ 0] 32 bytes PetscPushErrorHandler() at ...".
        CHECK_THAT(r.out + r.err, !Catch::Contains(" bytes "));
    }
}
