// The Campbell glue of the rotating frame's pencils
// (src/analyses/campbell/zero_frequency_crossings.hpp): which ratios r an
// excitation order needs, and how the pencils' exact crossings replace the
// sweep's. No solve: the solves are tested in
// tests/verification/test_rotating_frame_critical.cpp.
#include "analyses/campbell/zero_frequency_crossings.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

namespace {

WhirlCrossing crossing(int order, Whirl whirl, double speed_hz, CrossingSource source) {
    WhirlCrossing c;
    c.order = order;
    c.whirl = whirl;
    c.speed_hz = speed_hz;
    c.source = source;
    return c;
}

}  // namespace

TEST_CASE("The pencils' ratios: |r - k| = j for the bending pair and harmonic 0", "[campbell][rotating_frame]") {
    // Order 1: r = 1 (k = 0), r = 2 (k = +1, backward); r = 0 is the
    // zero-frequency pencil. Order 2 adds r = 1 (k = -1, forward) and
    // r = 3 (k = +1, backward), and r = 2 for k = 0.
    CHECK(crossing_ratios({1}) == std::vector<int>{1, 2});
    CHECK(crossing_ratios({1, 2}) == std::vector<int>{1, 2, 3});
    CHECK(crossing_ratios({2}) == std::vector<int>{1, 2, 3});
    CHECK(crossing_ratios({}).empty());
}

TEST_CASE("A pencil crossing replaces the sweep's of the same order and whirl only", "[campbell][rotating_frame]") {
    CampbellResult r;
    r.critical = {crossing(2, Whirl::backward, 25.265, CrossingSource::sweep),
                  crossing(2, Whirl::forward, 25.325, CrossingSource::sweep)};
    // The backward one again, from the pencil r = 3, within 1e-3 of the sweep's.
    merge_pencil_crossings(r, {crossing(2, Whirl::backward, 25.2651, CrossingSource::pencil),
                               crossing(1, Whirl::backward, 50.508, CrossingSource::pencil)});
    REQUIRE(r.critical.size() == 3);
    CHECK(r.critical[0].source == CrossingSource::pencil);  // BW order 2: the pencil's, the sweep's dropped
    CHECK(r.critical[0].whirl == Whirl::backward);
    CHECK(r.critical[1].source == CrossingSource::sweep);  // FW order 2: no pencil crossing of that whirl given
    CHECK(r.critical[1].whirl == Whirl::forward);
    CHECK(r.critical[2].order == 1);  // ascending by speed
}
