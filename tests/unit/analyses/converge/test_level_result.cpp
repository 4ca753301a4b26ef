// A level's repeated runs summarized (analyses/converge/level_result.hpp):
// median timings, so that one disturbed run does not move them, and the
// largest peak memory.
#include "analyses/converge/level_result.hpp"

#include "support/test_modes.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;
using coremodal::testing::mode;

TEST_CASE("The median of repeated runs", "[converge]") {
    MeshStep step;
    LevelRun a, b, c;
    a.timing_s = {.mesh = 0.1, .assemble = 1.0, .factor_and_solve = 10.0, .classify = 0.2, .total = 11.3};
    b.timing_s = {.mesh = 0.2, .assemble = 1.2, .factor_and_solve = 30.0, .classify = 0.2, .total = 31.6};  // disturbed
    c.timing_s = {.mesh = 0.1, .assemble = 1.1, .factor_and_solve = 11.0, .classify = 0.2, .total = 12.4};
    a.cpu_s = 11, b.cpu_s = 12, c.cpu_s = 30;
    a.solver_s = {1, 2, 3}, b.solver_s = {4, 5, 6}, c.solver_s = {7, 8, 9};
    a.peak_memory_mb = 500, b.peak_memory_mb = 520, c.peak_memory_mb = 510;
    a.modes = b.modes = c.modes = {mode(1, 32.1, "bending", 1, 0)};
    const LevelResult r = summarize_runs(step, {a, b, c});
    CHECK(r.runs == 3);
    CHECK(r.median_s.assemble == 1.1);
    CHECK(r.median_s.factor_and_solve == 11.0);
    CHECK(r.median_s.total == 12.4);
    CHECK(r.median_cpu_s == 12);
    CHECK(r.median_solver_s.factor_s == 4);
    CHECK(r.median_solver_s.orthogonalize_s == 6);
    CHECK(r.peak_memory_mb == 520);
    CHECK(r.complete);
    CHECK(r.max_repeat_spread == 0);

    SECTION("Runs that disagree in frequency or completeness are reported") {
        c.modes = {mode(1, 32.1 * (1 + 1e-6), "bending", 1, 0)};
        c.complete = false;
        const LevelResult s = summarize_runs(step, {a, b, c});
        CHECK_FALSE(s.complete);
        CHECK(s.max_repeat_spread == Approx(1e-6).epsilon(1e-5));
    }
}
