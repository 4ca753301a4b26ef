// Grouping degenerate modes, the assignment and the tracks (modes/tracking.hpp),
// on synthetic signatures where the right answer is known.
#include "modes/tracking.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

namespace {

ModeSummary mode(int index, double f, const std::string& type, int n, int m, Signature s) {
    ModeSummary out;
    out.index = index;
    out.frequency_hz = f;
    out.label = {type, n, m, 1.0};
    out.signature = std::move(s);
    return out;
}

Signature unit(int i, int size = 6) {
    Signature s(size, 0.0);
    s[i] = 1;
    return s;
}

int track_of(const std::vector<ModeGroup>& groups, const std::vector<TrackStep>& steps, const std::string& type) {
    for (size_t i = 0; i < groups.size(); ++i)
        if (groups[i].label.type == type) return steps[i].track;
    return -1;
}

}  // namespace

TEST_CASE("Degenerate pairs and all rigid modes are one group each; close distinct modes are not", "[tracking]") {
    const std::vector<ModeSummary> modes = {
        mode(1, 0.0, "rigid", 0, 0, unit(0)),
        mode(2, 1e-4, "rigid", 0, 0, unit(1)),
        mode(3, 100.0, "bending", 1, 0, unit(2)),
        mode(4, 100.0 * (1 + 1e-9), "bending", 1, 0, unit(3)),  // exact pair
        mode(5, 150.0, "ovalling", 2, 0, unit(4)),
        mode(6, 150.0 * (1 + 2e-3), "ovalling", 2, 0, unit(5)),  // a pair split by a non-symmetric mesh
        mode(7, 160.0, "ovalling", 2, 0, unit(0)),
        mode(8, 160.0 * (1 + 2e-3), "ovalling", 2, 1, unit(1)),  // same family, other m: two modes
    };
    const std::vector<ModeGroup> groups = group_modes(modes);
    REQUIRE(groups.size() == 5);
    CHECK(groups[0].members == std::vector<int>{0, 1});
    CHECK(groups[1].members == std::vector<int>{2, 3});
    CHECK(groups[2].members == std::vector<int>{4, 5});
    CHECK(groups[3].members == std::vector<int>{6});
    CHECK(groups[4].members == std::vector<int>{7});
    CHECK(groups[1].signatures.size() == 2);
}

TEST_CASE("The assignment maximises the total MAC, where picking the best first would not", "[tracking]") {
    // Greedy takes (0,0) = 0.9 and is left with (1,1) = 0.1: total 1.0.
    // The optimum is (0,1) + (1,0) = 0.8 + 0.85 = 1.65.
    const std::vector<std::vector<double>> w = {{0.9, 0.8}, {0.85, 0.1}};
    CHECK(assign_maximum(w) == std::vector<int>{1, 0});
    SECTION("More rows than columns leave a row unassigned") {
        const std::vector<std::vector<double>> tall = {{0.1}, {0.9}, {0.2}};
        CHECK(assign_maximum(tall) == std::vector<int>{-1, 0, -1});
    }
    SECTION("More columns than rows") {
        const std::vector<std::vector<double>> wide = {{0.1, 0.2, 0.95}, {0.3, 0.9, 0.99}};
        CHECK(assign_maximum(wide) == std::vector<int>{2, 1});
    }
}

TEST_CASE("Two modes that cross in frequency keep their tracks", "[tracking]") {
    // Point A: bending below torsion; point B: torsion below bending. The
    // frequency order swaps, the signatures do not.
    int next = 1;
    const auto a = group_modes({mode(1, 100, "bending", 1, 0, unit(0)), mode(2, 100, "bending", 1, 0, unit(1)),
                                mode(3, 120, "torsion", 0, 0, unit(2))});
    const auto steps_a = start_tracks(a, next);
    const auto b = group_modes({mode(1, 90, "torsion", 0, 0, unit(2)), mode(2, 110, "bending", 1, 0, unit(1)),
                                mode(3, 110, "bending", 1, 0, unit(0))});
    std::vector<int> tracks_a;
    for (const auto& s : steps_a) tracks_a.push_back(s.track);
    const auto steps_b = follow_tracks(a, tracks_a, b, next);
    CHECK(track_of(b, steps_b, "bending") == track_of(a, steps_a, "bending"));
    CHECK(track_of(b, steps_b, "torsion") == track_of(a, steps_a, "torsion"));
    for (const auto& s : steps_b) {
        CHECK_FALSE(s.ambiguous);
        CHECK_FALSE(s.new_track);
        CHECK(*s.mac_previous == Approx(1));
    }
    CHECK(next == 3);  // no new track
}

TEST_CASE("A mode that enters the window starts a new track; a mixed match is ambiguous", "[tracking]") {
    int next = 1;
    const auto a = group_modes({mode(1, 100, "bending", 1, 0, unit(0)), mode(2, 200, "torsion", 0, 0, unit(2))});
    const auto steps_a = start_tracks(a, next);
    const std::vector<int> tracks_a = {steps_a[0].track, steps_a[1].track};
    SECTION("New mode") {
        const auto b = group_modes({mode(1, 90, "axial", 0, 0, unit(4)), mode(2, 95, "bending", 1, 0, unit(0))});
        const auto steps = follow_tracks(a, tracks_a, b, next);
        CHECK(steps[0].new_track);
        CHECK(steps[0].track == 3);
        CHECK(steps[1].track == tracks_a[0]);
    }
    SECTION("A good match with a rival close behind is still ambiguous") {
        // MAC 0.9 to the bending track and 0.85 to a second current group: within 0.1.
        const double best = std::sqrt(0.9), rival = std::sqrt(0.85);
        const auto b = group_modes({mode(1, 95, "bending", 1, 0, {best, 0, 0, 0, std::sqrt(0.1), 0}),
                                    mode(2, 99, "mixed", 1, 1, {rival, 0, 0, std::sqrt(0.15), 0, 0})});
        const auto steps = follow_tracks(a, tracks_a, b, next);
        CHECK(*steps[0].mac_previous == Approx(0.9));
        CHECK(steps[0].ambiguous);
    }
    SECTION("A mode that is half one and half the other") {
        Signature half = {std::sqrt(0.5), 0, std::sqrt(0.5), 0, 0, 0};
        const auto b = group_modes({mode(1, 150, "mixed", 0, 0, half)});
        const auto steps = follow_tracks(a, tracks_a, b, next);
        CHECK(steps[0].ambiguous);
        CHECK(*steps[0].mac_previous == Approx(0.5));
    }
}

TEST_CASE("Modes without signatures (a model that gives none) are matched by label", "[tracking]") {
    int next = 1;
    const auto a = group_modes({mode(1, 100, "bending", 1, 0, {}), mode(2, 100, "bending", 1, 0, {}),
                                mode(3, 120, "torsion", 0, 0, {})});
    const auto steps_a = start_tracks(a, next);
    const auto b = group_modes({mode(1, 90, "torsion", 0, 0, {}), mode(2, 110, "bending", 1, 0, {}),
                                mode(3, 110, "bending", 1, 0, {})});
    const auto steps_b = follow_tracks(a, {steps_a[0].track, steps_a[1].track}, b, next);
    CHECK(track_of(b, steps_b, "bending") == track_of(a, steps_a, "bending"));
    CHECK(track_of(b, steps_b, "torsion") == track_of(a, steps_a, "torsion"));
}
