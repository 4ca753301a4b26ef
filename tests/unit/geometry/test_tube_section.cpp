#include "geometry/tube_section.hpp"

#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace coremodal;

TEST_CASE("Axial segments end on clamp edges and the free core is graded towards them", "[geometry]") {
    // Clamp zones 100 mm long centred 250 mm from each end of a 4.32 m core
    // (case 03): overhang, clamp, span, clamp, overhang.
    Scene s = testing::steel_tube(0.176, 0.1505, 4.32, 2, 16, 60);
    s.supports.kind = SupportKind::clamped;
    s.supports.clamps = {{"left", 0.2, 0.3}, {"right", 4.02, 4.12}};
    const TubeSection section = make_tube_section(s);
    REQUIRE(section.segments.size() == 5);
    CHECK(section.segments[0].grading == AxialGrading::toward_end);    // overhang, clamp on its right
    CHECK(section.segments[1].grading == AxialGrading::uniform);       // inside the clamp
    CHECK(section.segments[2].grading == AxialGrading::toward_both);   // the free span
    CHECK(section.segments[3].grading == AxialGrading::uniform);
    CHECK(section.segments[4].grading == AxialGrading::toward_start);  // overhang, clamp on its left
    CHECK(section.segments[2].z_start == Approx(0.3));
    CHECK(section.segments[2].z_end == Approx(4.02));
    int total = 0;
    for (const auto& seg : section.segments) {
        CHECK(seg.n_elements >= 2);
        total += seg.n_elements;
    }
    CHECK(total >= 60);
}

TEST_CASE("Clamps at the core ends leave no graded overhang; a free core is uniform", "[geometry]") {
    Scene s = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 2.211, 2, 16, 40), 0.07);
    const TubeSection clamped = make_tube_section(s);
    REQUIRE(clamped.segments.size() == 3);
    CHECK(clamped.segments[1].grading == AxialGrading::toward_both);
    const TubeSection free = make_tube_section(testing::steel_tube(0.106, 0.076, 2.211, 2, 16, 40));
    REQUIRE(free.segments.size() == 1);
    CHECK(free.segments[0].grading == AxialGrading::uniform);
}

TEST_CASE("The chucks' node count without meshing equals gmsh's", "[long][geometry][chucks]") {
    // At 48 around the shaft's ring of the O-grid needs two elements across
    // (half the shaft radius wide, > 3 x the 3.9 mm around); fewer, one.
    for (int around : {8, 16, 48}) {
        const Scene s = testing::with_chucks(testing::paper_core(0.5, around, 12), InterfaceKind::spring);
        const TubeSection section = make_tube_section(s);
        // The tube by hand: hex20 layers of r elements through, t around and
        // z along: corner-layer nodes (vertices and mid-edges of the section)
        // and mid-layer nodes (vertices only).
        long z = 0;
        for (const AxialSegment& seg : section.segments) z += seg.n_elements;
        const long r = section.layers.front().n_elements, t = around;
        const long tube = t * ((r + 1) * (z + 1) + r * (z + 1) + (r + 1) * (z + 1) + (r + 1) * z);
        INFO("around " << around);
        CHECK(tube + count_chuck_hex20_nodes(section) == testing::generated_mesh(s).n_nodes());
    }
}

TEST_CASE("A span clamped at both ends is graded by 8 from each clamp edge to its middle", "[geometry]") {
    // The mesh's axial element edges over the span between 70 mm clamps:
    // geometric growth by kClampEdgeGradingRatio = 8 from each edge to the
    // middle (a regression once graded each half by only sqrt(8), which cost
    // case 02's default mesh 0.07 % in f1).
    const Scene s = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 2.211, 1, 8, 40), 0.07);
    std::vector<double> z;
    for (const auto& p : testing::generated_mesh(s).nodes)
        if (p[2] > 0.07 - 1e-9 && p[2] < 2.211 - 0.07 + 1e-9) z.push_back(p[2]);
    std::sort(z.begin(), z.end());
    z.erase(std::unique(z.begin(), z.end(), [](double a, double b) { return b - a < 1e-9; }), z.end());
    // hex20: corner layers at even positions, mid-edge layers between them.
    std::vector<double> lengths;
    for (size_t i = 2; i < z.size(); i += 2) lengths.push_back(z[i] - z[i - 2]);
    REQUIRE(lengths.size() >= 8);
    const auto [shortest, longest] = std::minmax_element(lengths.begin(), lengths.end());
    CHECK(*longest / *shortest == Approx(8.0).epsilon(1e-6));
    CHECK(lengths.front() == Approx(*shortest));  // small at the clamp edges
    CHECK(lengths.back() == Approx(*shortest));
}
