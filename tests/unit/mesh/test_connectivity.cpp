#include "mesh/connectivity.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

namespace {

// Two tet10 cells; `shared` decides whether they share a corner node.
Mesh two_tets(bool shared) {
    Mesh m;
    m.cell_type = CellType::tet10;
    m.part_names = {"core", "rest_paper"};
    m.nodes.resize(20, {0, 0, 0});
    for (int a = 0; a < 10; ++a) m.cells.push_back(a);
    for (int a = 0; a < 10; ++a) m.cells.push_back(10 + a);
    if (shared) m.cells[10] = 0;  // the second cell's first corner is the first cell's
    m.cell_part = {0, 1};
    return m;
}

}  // namespace

TEST_CASE("Cells that share a node form one component; disjoint ones two", "[mesh][connectivity]") {
    CHECK(connected_components(two_tets(true)).size() == 1);
    const auto parts = connected_components(two_tets(false));
    REQUIRE(parts.size() == 2);
    CHECK(parts[0].cells.size() == 1);
    CHECK(parts[1].cells.size() == 1);
}

TEST_CASE("A part not connected to the clamped nodes is named; a free scene names none", "[mesh][connectivity]") {
    const Mesh loose = two_tets(false);
    const auto warnings = unheld_parts(loose, {3});  // node 3 belongs to the core cell
    REQUIRE(warnings.size() == 1);
    CHECK_THAT(warnings[0], Catch::Contains("'rest_paper'") && Catch::Contains("six rigid-body modes"));
    CHECK(unheld_parts(two_tets(true), {3}).empty());
    CHECK(unheld_parts(loose, {}).empty());
}
