// PETSc's own memory checks on a real run: -malloc_debug traces every
// PetscMalloc and -malloc_dump lists, at PetscFinalize, what was never freed
// (both work in Debian's optimized PETSc; -malloc_test and -objects_dump need
// a debug build of PETSc). A Mat, Vec, KSP or EPS that coremodal forgets to
// destroy shows up here, where AddressSanitizer's leak check cannot see it
// (scripts/lsan.supp leaves PETSc's allocations to this test).
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal::testing;

namespace {

// Steel, one element through the wall, 8 around, 4 along: a second to solve.
const std::string kTinyCase = R"(name = "tiny"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "0.5 m"
material = { E = "210 GPa", nu = 0.3, density = "7850 kg/m^3" }

[analysis]
modes = 12

[mesh]
around = 8
along = 4
through_wall = 1
)";

}  // namespace

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
