// modes.xdmf: the gmsh -> VTK node permutation (checked geometrically) and
// the temporal collection that ParaView steps through.
#include "output/mode_display.hpp"
#include "output/modes_h5.hpp"
#include "output/xdmf.hpp"
#include "unit/output/output_fixtures.hpp"

#include <cstdio>
#include <cstdlib>

using namespace coremodal;
using namespace coremodal::output_test;

// ---------------------------------------------------------------- tests

TEST_CASE("gmsh -> VTK hex20 permutation puts every VTK edge node mid-edge", "[output][xdmf]") {
    for (CellType type : {CellType::hex20, CellType::hex27}) {
        // hex27's first 20 nodes are numbered as hex20's; extra nodes don't matter.
        const std::vector<Point> gmsh = quadratic_cell_nodes(hex_corners(), gmsh_hex20_edges);
        const std::vector<int> order = vtk_node_order(type);
        REQUIRE(order.size() == 20);
        REQUIRE(vtk_nodes_per_cell(type) == 20);
        std::vector<Point> vtk;
        for (int g : order) vtk.push_back(gmsh[g]);
        for (int a = 0; a < 8; ++a) CHECK(order[a] == a);  // corners agree
        for (size_t e = 0; e < vtk_hex20_edges.size(); ++e) {
            const auto [a, b] = vtk_hex20_edges[e];
            const Point expected = midpoint(vtk[a], vtk[b]);
            INFO("VTK edge node " << 8 + e << " on edge (" << a << "," << b << ")");
            for (int c = 0; c < 3; ++c) CHECK(vtk[8 + e][c] == Approx(expected[c]));
        }
        std::vector<int> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        for (int i = 0; i < 20; ++i) CHECK(sorted[i] == i);  // a permutation
    }
}

TEST_CASE("gmsh -> VTK tet10 permutation puts every VTK edge node mid-edge", "[output][xdmf]") {
    const std::vector<Point> gmsh = quadratic_cell_nodes(tet_corners(), gmsh_tet10_edges);
    const std::vector<int> order = vtk_node_order(CellType::tet10);
    REQUIRE(order.size() == 10);
    std::vector<Point> vtk;
    for (int g : order) vtk.push_back(gmsh[g]);
    for (size_t e = 0; e < vtk_tet10_edges.size(); ++e) {
        const auto [a, b] = vtk_tet10_edges[e];
        const Point expected = midpoint(vtk[a], vtk[b]);
        INFO("VTK edge node " << 4 + e);
        for (int c = 0; c < 3; ++c) CHECK(vtk[4 + e][c] == Approx(expected[c]));
    }
}

TEST_CASE("vtk_cells applies the permutation to the mesh's node indices", "[output][xdmf]") {
    for (CellType type : {CellType::hex20, CellType::tet10}) {
        const Mesh mesh = one_cell_mesh(type);
        const std::vector<std::int64_t> vtk = vtk_cells(mesh);
        const std::vector<int> order = vtk_node_order(type);
        REQUIRE(vtk.size() == order.size());
        // Geometric check through the mesh's own node coordinates.
        const auto& edges = type == CellType::tet10 ? vtk_tet10_edges : vtk_hex20_edges;
        const size_t n_corners = type == CellType::tet10 ? 4 : 8;
        for (size_t e = 0; e < edges.size(); ++e) {
            const Point expected = midpoint(mesh.nodes[vtk[edges[e].first]],
                                            mesh.nodes[vtk[edges[e].second]]);
            const Point& actual = mesh.nodes[vtk[n_corners + e]];
            for (int c = 0; c < 3; ++c) CHECK(actual[c] == Approx(expected[c]));
        }
    }
}

TEST_CASE("grid names of the modes in the XDMF file", "[output][xdmf]") {
    Mode mode;
    mode.frequency_hz = 48.8;
    mode.label.type = "bending";
    mode.label.n = 1;
    CHECK(xdmf_mode_name(mode, 1, 20) == "mode_01_48.80Hz_bending_n1_m0");
    mode.frequency_hz = -1e-6;
    mode.label.type = "rigid";
    mode.label.n = 0;
    CHECK(xdmf_mode_name(mode, 7, 120) == "mode_007_0.00Hz_rigid_n0_m0");
}

namespace {

// Counts non-overlapping occurrences of `what` in `text`.
size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

// Runs a python check on the XDMF file with an independent XML parser, when
// python is at hand; `check` sees the root element as `r` and must be true.
void check_with_python(const std::string& xdmf, const std::string& check) {
    if (!fs::exists("/usr/bin/python3")) return;
    const std::string command = "/usr/bin/python3 -c 'import sys, xml.etree.ElementTree as E; "
                                "r = E.parse(sys.argv[1]).getroot(); sys.exit(0 if (" +
                                check + ") else 1)' " + xdmf;
    INFO(command);
    CHECK(std::system(command.c_str()) == 0);
}

}  // namespace

TEST_CASE("write_modes_xdmf writes the modes as time steps pointing into modes.h5", "[output][xdmf]") {
    TempDir dir;
    for (CellType type : {CellType::hex20, CellType::tet10}) {
        const Mesh mesh = one_cell_mesh(type);
        const std::vector<Mode> modes = fake_modes(mesh.n_nodes());
        write_modes_h5(dir.file("modes.h5"), mesh, modes, "tiny", case_json, "1");
        const std::string xdmf = dir.file("modes.xdmf");
        write_modes_xdmf(xdmf, "modes.h5", mesh, modes);

        const std::string text = slurp(xdmf);
        const std::string n = std::to_string(mesh.n_nodes());
        CHECK_THAT(text, Catch::Contains("GridType=\"Collection\" CollectionType=\"Temporal\""));
        // One grid per mode, time = mode number, each on the same mesh datasets.
        CHECK_THAT(text, Catch::Contains("<Time Value=\"1\"/>") && Catch::Contains("<Time Value=\"2\"/>"));
        CHECK(count(text, std::string("TopologyType=\"") + xdmf_topology_type(type) + "\"") == 2);
        CHECK(count(text, "Dimensions=\"1 " + std::to_string(vtk_nodes_per_cell(type)) + "\"") == 2);
        CHECK(count(text, "modes.h5:/mesh/vtk_cells") == 2);
        CHECK(count(text, "modes.h5:/mesh/nodes") == 2);
        CHECK(count(text, "Name=\"part\"") == 2);
        CHECK_THAT(text, Catch::Contains("Name=\"mode_01_0.00Hz_rigid_n0_m0\""));
        CHECK_THAT(text, Catch::Contains("Name=\"mode_02_48.80Hz_bending_n1_m2\""));
        CHECK_THAT(text, Catch::Contains("Value=\"mode 2: 48.80 Hz, bending, n=1, m=2\""));
        CHECK_THAT(text, Catch::Contains("modes.h5:/modes/shapes/mode_0002"));
        CHECK_THAT(text, Catch::Contains("Name=\"display_displacement\" AttributeType=\"Vector\"") &&
                             Catch::Contains("modes.h5:/modes/display/mode_0002"));
        for (const char* component : {"u_r", "u_theta", "u_z"})
            CHECK_THAT(text, Catch::Contains(std::string("Name=\"") + component + "\"") &&
                                 Catch::Contains("modes.h5:" + modes_h5_component_dataset(component, 2)));
        // "bending" as character codes: b=98 e=101 n=110 d=100 i=105 n=110 g=103.
        CHECK_THAT(text, Catch::Contains(">98 101 110 100 105 110 103</DataItem>"));

        // Every grid: part, displacement, display_displacement, u_r, u_theta, u_z and 6 field values.
        check_with_python(xdmf, "len(r.findall(\"./Domain/Grid/Grid\")) == 2 and "
                                "all(len(g.findall(\"Attribute\")) == 12 for g in r.iter(\"Grid\") if g.find(\"Time\") is not None) and "
                                "[g.find(\"Time\").get(\"Value\") for g in r.findall(\"./Domain/Grid/Grid\")] == [\"1\", \"2\"]");
    }
}

TEST_CASE("write_modes_xdmf gives each mode its frequency, numbers and warp scale as field data", "[output][xdmf]") {
    TempDir dir;
    const Mesh mesh = one_cell_mesh(CellType::hex20);
    std::vector<Mode> modes = fake_modes(mesh.n_nodes());
    modes[1].frequency_hz = 48.812345678901234;
    const std::string xdmf = dir.file("modes.xdmf");
    write_modes_xdmf(xdmf, "modes.h5", mesh, modes);
    const std::string text = slurp(xdmf);
    auto field = [](const std::string& name, const std::string& value) {
        return "<Attribute Name=\"" + name + "\" AttributeType=\"Scalar\" Center=\"Grid\">\n" +
               "          <DataItem Dimensions=\"1\" NumberType=\"" + (name == "frequency_hz" || name == "warp_scale" ? "Float\" Precision=\"8" : "Int\" Precision=\"4") +
               "\" Format=\"XML\">" + value + "</DataItem>";
    };
    CHECK_THAT(text, Catch::Contains(field("mode", "2")));
    // All 17 significant digits, so that the number reads back exactly.
    const std::string frequency = "48.812345678901231";
    CHECK(std::strtod(frequency.c_str(), nullptr) == modes[1].frequency_hz);
    CHECK_THAT(text, Catch::Contains(field("frequency_hz", frequency)));
    CHECK_THAT(text, Catch::Contains(field("n", "1")) && Catch::Contains(field("m", "2")));
    char scale[40];
    std::snprintf(scale, sizeof scale, "%.17g", suggested_warp_scale(mesh, modes[1].shape, "bending"));
    CHECK_THAT(text, Catch::Contains(field("warp_scale", scale)));
}

TEST_CASE("write_modes_xdmf without modes writes the mesh alone", "[output][xdmf]") {
    TempDir dir;
    const Mesh mesh = one_cell_mesh(CellType::hex20);
    const std::string xdmf = dir.file("modes.xdmf");
    write_modes_xdmf(xdmf, "modes.h5", mesh, {});
    const std::string text = slurp(xdmf);
    CHECK_THAT(text, Catch::Contains("GridType=\"Uniform\"") && Catch::Contains("modes.h5:/mesh/nodes"));
    CHECK_THAT(text, !Catch::Contains("Temporal") && !Catch::Contains("<Time"));
    check_with_python(xdmf, "len(r.findall(\"./Domain/Grid/Attribute\")) == 1");
}

TEST_CASE("write_modes_xdmf reports an unwritable path", "[output][xdmf]") {
    TempDir dir;
    const Mesh mesh = one_cell_mesh(CellType::hex20);
    const std::string path = dir.file("no/such/dir/modes.xdmf");
    CHECK_THROWS_WITH(write_modes_xdmf(path, "modes.h5", mesh, {}), Catch::Contains(path));
}
