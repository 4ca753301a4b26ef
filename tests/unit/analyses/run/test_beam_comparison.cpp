// f1 (and with it the chuck factor k = f1 / f2) is the roll's first bending
// mode in the vertical plane (y-z; gravity along -y), never a mode in which
// the roll moves rigidly on its supports (issue 33, item 13; docs/chucks.md).
#include "analyses/run/run.hpp"

#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

Mode mode(int index, double hz, const std::string& type, double mass_x, double mass_y) {
    Mode m;
    m.index = index;
    m.frequency_hz = hz;
    m.eigenvalue = std::pow(2 * M_PI * hz, 2);
    m.label = {type, type == "torsion" ? 0 : 1, 0, 0.9};
    m.effective_mass.x = mass_x;
    m.effective_mass.y = mass_y;
    return m;
}

}  // namespace

TEST_CASE("f1 is the first bending mode in the vertical plane, past support modes and horizontal bending",
          "[run][beam_comparison]") {
    const Scene s = clamp_both_ends(paper_core(2.0), 0.07);
    // A roll on chucks not expanded: it swings sideways on its contact arcs
    // (support), then bends sideways (horizontal: effective mass in x), then
    // vertically (y).
    const std::vector<Mode> modes = {mode(1, 12.0, "support", 9.0, 0.0), mode(2, 30.0, "bending", 6.0, 0.1),
                                     mode(3, 41.0, "bending", 0.1, 6.0), mode(4, 80.0, "torsion", 0, 0)};
    const BeamComparison b = compare_with_beam(s, modes);
    CHECK(b.fe_first_bending_hz == 41.0);
    CHECK(b.fe_mode_index == 3);
    // A degenerate pair of a body of revolution: either member's frequency.
    const BeamComparison pair =
        compare_with_beam(s, {mode(1, 61.4, "bending", 4.6, 1.4), mode(2, 61.4, "bending", 1.4, 4.6)});
    CHECK(pair.fe_first_bending_hz == 61.4);
    // Modes with no translational effective mass cannot tell their plane:
    // the first bending mode.
    CHECK(compare_with_beam(s, {mode(1, 20.0, "bending", 0, 0), mode(2, 25.0, "bending", 0, 0)}).fe_first_bending_hz ==
          20.0);
    // Only horizontal bending modes found: none, and the reason says so.
    const BeamComparison horizontal = compare_with_beam(s, {mode(1, 30.0, "bending", 6.0, 0.1)});
    CHECK(horizontal.fe_first_bending_hz == 0);
    CHECK_THAT(horizontal.fe_missing, Catch::Matchers::Contains("horizontal plane"));
}
