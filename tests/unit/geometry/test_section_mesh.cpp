// The harmonic level's r–z section mesh is the solid's section: the same
// nodes in every r–z plane, interfaces facing at the same z, the axis on
// r = 0; and its revolution into hex20 cells for showing the modes.
#include "geometry/section_mesh.hpp"

#include "modes/classify.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

using namespace coremodal;

namespace {

Scene chuck_scene() {
    Scene s = testing::with_chucks(testing::paper_core(0.8, 16, 16), InterfaceKind::spring);
    s.rest_paper = RestPaperSpec{0.126, testing::paperboard()};
    return s;
}

// (r, z) to 0.1 micrometre.
std::pair<long, long> key(double r, double z) { return {std::lround(r * 1e7), std::lround(z * 1e7)}; }

}  // namespace

TEST_CASE("Section mesh: the roll's nodes are those of the solid's r-z planes", "[long][geometry][harmonic]") {
    const Scene s = chuck_scene();
    const SectionMesh section = make_section_mesh(make_tube_section(s), s.supports.clamps);
    const Mesh solid = testing::generated_mesh(s);
    std::set<std::pair<long, long>> solid_points;
    for (int n : roll_nodes(solid))
        solid_points.insert(key(std::hypot(solid.nodes[n][0], solid.nodes[n][1]), solid.nodes[n][2]));
    // Every section node of the roll is a node of the solid in each r-z plane
    // it was extruded through, and the solid has no station along z the
    // section lacks. (Not every solid node is a section node: gmsh puts the
    // mid-edge nodes of the wall's interior rings on the chord, r cos(pi/n)
    // inside the arc.)
    std::set<long> section_z, solid_z;
    for (const auto& x : section.nodes) section_z.insert(std::lround(x[1] * 1e7));
    for (const auto& p : solid_points) solid_z.insert(p.second);
    std::set<std::pair<long, long>> section_roll;
    for (int c = 0; c < section.n_cells(); ++c) {
        const std::string& part = section.part_names[section.cell_part[c]];
        if (part != "core" && part != "rest_paper") continue;
        for (int a : section.cells[c]) section_roll.insert(key(section.nodes[a][0], section.nodes[a][1]));
    }
    for (const auto& p : section_roll) {
        INFO("section node at r = " << p.first * 1e-7 << ", z = " << p.second * 1e-7);
        CHECK(solid_points.count(p) == 1);
    }
    for (long z : solid_z) CHECK(section_z.count(z) == 1);
}

TEST_CASE("Section mesh: interfaces face each other, the axis is at r = 0; its revolution into hex20",
          "[geometry][harmonic]") {
    const Scene s = chuck_scene();
    const SectionMesh section = make_section_mesh(make_tube_section(s), s.supports.clamps);
    for (const std::string end : {"left", "right"}) {
        const auto& core = section.edge_groups.at("interface_" + end + "_core");
        const auto& chuck = section.edge_groups.at("interface_" + end + "_chuck");
        REQUIRE(core.size() == chuck.size());
        double covered = 0;
        for (size_t k = 0; k < core.size(); ++k) {
            for (int p = 0; p < 3; ++p) {
                CHECK(section.nodes[core[k][p]][1] == Approx(section.nodes[chuck[k][p]][1]).margin(1e-9));
                CHECK(section.nodes[core[k][p]][0] == Approx(s.core.inner_diameter / 2));
                CHECK(section.nodes[chuck[k][p]][0] == Approx(s.supports.chucks[0].body_diameter / 2));
            }
            covered += std::abs(section.nodes[core[k][1]][1] - section.nodes[core[k][0]][1]);
        }
        CHECK(covered == Approx(s.supports.chucks[0].expanding[0].width));  // the band, exactly
        // The bearing face spans the shaft from the axis.
        double r_max = 0;
        for (const auto& e : section.edge_groups.at("bearing_" + end))
            for (int node : e) r_max = std::max(r_max, section.nodes[node][0]);
        CHECK(r_max == Approx(s.supports.chucks[0].shaft_diameter / 2));
    }
    for (int node : section.node_groups.at("axis")) CHECK(section.nodes[node][0] == 0.0);
    const RevolvedMesh revolved = revolve_section(section, 16);
    CHECK(revolved.mesh.n_cells() == 16 * section.n_cells());
    // Nodes on the axis are one per section node; elsewhere one per angle used.
    std::set<int> axis_3d;
    for (size_t i = 0; i < revolved.section_node.size(); ++i)
        if (section.nodes[revolved.section_node[i]][0] == 0.0) axis_3d.insert(revolved.section_node[i]);
    CHECK(axis_3d.size() == section.node_groups.at("axis").size());
    for (const auto& x : revolved.mesh.nodes) CHECK(std::isfinite(x[0] + x[1] + x[2]));
}

TEST_CASE("Section mesh: a chuck whose shaft is as wide as its body still faces the core over its band",
          "[geometry][harmonic]") {
    Scene s = chuck_scene();
    for (ChuckSpec& c : s.supports.chucks) c.shaft_diameter = c.body_diameter;
    const SectionMesh section = make_section_mesh(make_tube_section(s), s.supports.clamps);
    for (const std::string end : {"left", "right"}) {
        REQUIRE(section.edge_groups.count("interface_" + end + "_chuck") == 1);
        const auto& chuck = section.edge_groups.at("interface_" + end + "_chuck");
        CHECK(chuck.size() == section.edge_groups.at("interface_" + end + "_core").size());
        for (const auto& e : chuck) CHECK(section.nodes[e[0]][0] == Approx(s.supports.chucks[0].body_diameter / 2));
    }
}
