// Nothing nonsensical reported as verified, and no raw solver error, crash
// or hang reaching the user (issue 33, items 7-9), on the real program:
// exit status, the message by its words, nothing written.
#include "support/program_run.hpp"
#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <cstdlib>
#include <string>
#include <thread>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Case 15 with its left chuck on an elastic bearing of these springs.
std::string case_15_on_bearing(const std::string& radial, const std::string& tilting) {
    std::string text = slurp(COREMODAL_SOURCE_DIR "/cases/15-rest-roll-on-web-76x15-2211.toml");
    text.replace(text.find("[[supports.left.expanding]]"), 0,
                 "[supports.left.bearing]\nradial_stiffness = " + radial + "\ntilting_stiffness = " + tilting + "\n\n");
    return text;
}

void check_refused_before_work(const Run& r, const TempDir& dir) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 1);
    CHECK_FALSE(contains(r.err, "PETSc error"));
    CHECK_FALSE(contains(r.out, "verification:"));  // no mode table: nothing reported as verified
    CHECK_FALSE(fs::exists(dir.path / "out"));
}

}  // namespace

TEST_CASE("Case 15 at the beam level with springs or a span beyond rigid is refused, nothing written",
          "[app][verify_gate]") {
    TempDir dir("verify");
    // Today's main: "max residual inf ... complete", f1 = 27 x Timoshenko, exit 0.
    dir.write("tilting.toml", case_15_on_bearing("\"200 kN/mm\"", "1e300"));
    const Run tilting = run_coremodal(dir, "run tilting.toml --model beam -o out --no-plots");
    check_refused_before_work(tilting, dir);
    CHECK(contains(tilting.err, "tilting.toml:"));
    CHECK(contains(tilting.err, "tilting_stiffness = 1e+300 is beyond rigid for this roll"));

    std::string span = slurp(COREMODAL_SOURCE_DIR "/cases/15-rest-roll-on-web-76x15-2211.toml");
    span.replace(span.find("span = \"1.2 m\""), 14, "span = 1.2e-300");
    dir.write("span.toml", span);
    const Run short_span = run_coremodal(dir, "run span.toml --model beam -o out --no-plots");
    check_refused_before_work(short_span, dir);
    CHECK(contains(short_span.err, "expected a span of at least"));
}

TEST_CASE("The option --keep-going belongs to run and campbell, and a verified run is unchanged by it",
          "[app][verify_gate]") {
    TempDir dir("verify");
    dir.write("ok.toml", case_15_on_bearing("\"200 kN/mm\"", "\"1 MN*m/rad\""));
    const Run r = run_coremodal(dir, "run ok.toml --model beam -o out -q --no-plots --keep-going");
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 0);
    CHECK_FALSE(contains(r.err, "verification failed"));
    CHECK(fs::exists(dir.path / "out" / "summary.json"));
    for (const char* command : {"run", "campbell"})
        CHECK(contains(run_coremodal(dir, std::string(command) + " --help").out, "--keep-going"));
}

TEST_CASE("A -max_memory_mb of abc is refused with what is expected, not PETSc's error 63", "[app][verify_gate]") {
    TempDir dir("verify");
    dir.write("tiny.toml", kTinyCase);
    const Run r = run_coremodal(dir, "run tiny.toml --model harmonic -o out --no-plots -max_memory_mb abc");
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.err, "-max_memory_mb abc: expected the memory this run may take, a positive number of MB"));
    CHECK_FALSE(contains(r.err, "PETSc error"));
    CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("Out of memory under an address-space limit is a clear error, no crash, no hang", "[app][verify_gate]") {
    // Case 08 on the coarse mesh: under 600 MB OpenBLAS retried a failed
    // allocation forever (97 % CPU); under 400 MB gmsh's std::bad_alloc
    // ended the program before main (exit 134), then, with that caught, the
    // error was said and the program hung at exit: OpenBLAS's second thread,
    // started as the library loaded, retried its 128 MB buffer forever and
    // OpenBLAS's exit handler waited for it (common/blas_threads.hpp).
    TempDir dir("verify");
    const std::string case_08 = "run '" COREMODAL_SOURCE_DIR "/cases/08-news-chucks-76x15-2200.toml' --mesh coarse -o out --no-plots";
    for (const long limit_kb : {400000L, 600000L}) {
        INFO("ulimit -v " << limit_kb);
        Started started = start_coremodal(dir, case_08, "prlimit --as=" + std::to_string(limit_kb * 1024));
        const std::optional<Run> r = finish_coremodal(dir, started, 60);
        REQUIRE(r);  // no hang
        INFO("stdout: " << r->out << "\nstderr: " << r->err);
        CHECK(r->exit_code == 1);
        CHECK(contains(r->err, "out of memory"));
        CHECK(contains(r->err, "address-space limit"));
        CHECK(contains(r->err, "ulimit -v"));
        CHECK_FALSE(contains(r->err, "terminate called"));
        CHECK_FALSE(fs::exists(dir.path / "out"));
    }
}

TEST_CASE("Under an address-space limit that affords one BLAS thread a run completes on one and says so",
          "[app][verify_gate]") {
    // 850 MB: room for the libraries (255 MB), their start (120 MB), a run's
    // least headroom (400 MB) and one BLAS thread; not for a second thread's
    // 200 MB (common/blas_threads.hpp). Before: that thread retried its
    // buffer forever, at 100 % CPU, and the program hung at exit.
    TempDir dir("verify");
    dir.write("tiny.toml", kTinyCase);
    Started started = start_coremodal(dir, "run tiny.toml -o out -q --no-plots", "prlimit --as=" + std::to_string(850000L * 1024));
    const std::optional<Run> r = finish_coremodal(dir, started, 120);
    REQUIRE(r);  // no hang
    INFO("stdout: " << r->out << "\nstderr: " << r->err);
    CHECK(r->exit_code == 0);
    CHECK(fs::exists(dir.path / "out" / "summary.json"));
    // The note only where OpenBLAS would have started more than one thread.
    if (std::thread::hardware_concurrency() > 1 && !std::getenv("OPENBLAS_NUM_THREADS") && !std::getenv("OMP_NUM_THREADS"))
        CHECK(contains(r->err, "BLAS on 1 thread instead of"));
}
