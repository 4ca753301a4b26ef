// Following modes across meshes by label (modes/label_tracking.hpp):
// degenerate partners are one mode, occurrences of one label are told
// apart, and tracks hold the labels every run has plus the role modes.
#include "modes/label_tracking.hpp"

#include "support/test_modes.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace coremodal;
using coremodal::testing::mode;

TEST_CASE("Degenerate partners are one mode; rigid and mixed modes are not tracked", "[converge][modes]") {
    const std::vector<Mode> modes = {
        mode(1, 0.0, "rigid", 0, 0),          mode(2, 1e-4, "rigid", 0, 0),
        mode(3, 133.36, "bending", 1, 2),     mode(4, 133.36 * (1 + 1e-9), "bending", 1, 2),
        mode(5, 466.2, "torsion", 0, 1),      mode(6, 600.0, "mixed", 1, 0),
        mode(7, 1030.83, "ovalling", 2, 0),   mode(8, 1030.84, "ovalling", 2, 0),
        mode(9, 1400.0, "ovalling", 2, 0)};  // a second, distinct n=2 m=0 mode
    const auto d = distinct_modes(modes);
    REQUIRE(d.size() == 4);
    CHECK(d[0].key == ModeKey{"bending", 1, 2, 1});
    CHECK(d[0].multiplicity == 2);
    CHECK(d[0].index == 3);
    CHECK(d[1].key == ModeKey{"torsion", 0, 1, 1});
    CHECK(d[2].key == ModeKey{"ovalling", 2, 0, 1});
    CHECK(d[2].multiplicity == 2);
    CHECK(d[3].key == ModeKey{"ovalling", 2, 0, 2});
    CHECK(d[3].key.text() == "ovalling n=2 m=0 #2");
    CHECK(d[0].key.text() == "bending n=1 m=2");
    CHECK(has_mode_type(modes, "ovalling"));
    CHECK_FALSE(has_mode_type(modes, "axial"));
    CHECK_FALSE(has_mode_type(modes, "mixed"));  // left out, as for tracking
}

TEST_CASE("Label tracks hold the keys of every run and the role modes of the last", "[converge][modes]") {
    // The bending pair and the torsion mode swap order between the runs; run 1
    // has no axial mode; run 2 adds it and a second torsion mode.
    const std::vector<Mode> coarse = {mode(1, 140.0, "bending", 1, 0), mode(2, 140.0, "bending", 1, 0),
                                      mode(3, 160.0, "torsion", 0, 0)};
    const std::vector<Mode> fine = {mode(1, 150.0, "torsion", 0, 0), mode(2, 165.0, "bending", 1, 0),
                                    mode(3, 165.0, "bending", 1, 0), mode(4, 800.0, "torsion", 0, 0),
                                    mode(5, 900.0, "axial", 0, 0)};
    const std::vector<ModeRole> roles = {{"f1", "bending"}, {"axial", "axial"}};
    const auto tracks = track_by_label({distinct_modes(coarse), distinct_modes(fine)}, roles);
    // The second torsion mode, missing in run 1 and no role, is not tracked.
    REQUIRE(tracks.size() == 3);
    // In the last run's order.
    CHECK(tracks[0].key == ModeKey{"torsion", 0, 0, 1});
    CHECK(tracks[0].role.empty());  // torsion is no role here
    CHECK(*tracks[0].frequency_hz[0] == 160.0);
    CHECK(*tracks[0].frequency_hz[1] == 150.0);
    CHECK(tracks[1].key == ModeKey{"bending", 1, 0, 1});
    CHECK(tracks[1].role == "f1");
    CHECK(*tracks[1].frequency_hz[0] == 140.0);
    // The axial mode is a role: tracked although run 1 lacks it.
    CHECK(tracks[2].key == ModeKey{"axial", 0, 0, 1});
    CHECK(tracks[2].role == "axial");
    CHECK_FALSE(tracks[2].frequency_hz[0]);
    CHECK(*tracks[2].frequency_hz[1] == 900.0);
    CHECK(track_by_label({}, roles).empty());
}
