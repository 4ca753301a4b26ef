// modes.h5 and modes.xdmf: write a tiny synthetic mesh with fake modes, read
// every dataset back with the HDF5 C API, and check the gmsh -> VTK node
// permutation geometrically.
#include "output/modes_h5.hpp"
#include "output/xdmf.hpp"

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace coremodal;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------- fixtures

using Point = std::array<double, 3>;

// A fresh directory per test, removed afterwards.
struct TempDir {
    fs::path path;
    TempDir() {
        static int counter = 0;
        path = fs::temp_directory_path() /
               ("coremodal_test_output_" + std::to_string(::getpid()) + "_" +
                std::to_string(counter++));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

Point midpoint(const Point& a, const Point& b) {
    return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

// A deliberately skewed trilinear map of the reference cube, so that no two
// distinct edges share a midpoint and a wrong permutation cannot pass by symmetry.
Point skew(double x, double y, double z) {
    return {1.0 + 0.9 * x + 0.1 * y + 0.05 * y * z, 2.0 + 1.3 * y + 0.2 * z + 0.07 * x * y,
            -0.5 + 0.7 * z + 0.15 * x + 0.03 * x * z};
}

// gmsh's hex20 edges, in the order of its edge nodes 8..19.
const std::vector<std::pair<int, int>> gmsh_hex20_edges = {
    {0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3}, {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
// VTK_QUADRATIC_HEXAHEDRON edges, in the order of its edge nodes 8..19.
const std::vector<std::pair<int, int>> vtk_hex20_edges = {
    {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
// gmsh's tet10 edges (nodes 4..9) and VTK_QUADRATIC_TETRA's.
const std::vector<std::pair<int, int>> gmsh_tet10_edges = {{0, 1}, {1, 2}, {2, 0},
                                                           {0, 3}, {2, 3}, {1, 3}};
const std::vector<std::pair<int, int>> vtk_tet10_edges = {{0, 1}, {1, 2}, {2, 0},
                                                          {0, 3}, {1, 3}, {2, 3}};

// Corners in gmsh order, then edge nodes at the midpoints of gmsh's edges.
std::vector<Point> quadratic_cell_nodes(const std::vector<Point>& corners,
                                        const std::vector<std::pair<int, int>>& gmsh_edges) {
    std::vector<Point> nodes = corners;
    for (auto [a, b] : gmsh_edges) nodes.push_back(midpoint(corners[a], corners[b]));
    return nodes;
}

std::vector<Point> hex_corners() {
    // gmsh (and VTK) corner order: bottom face counter-clockwise, then top.
    const int signs[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    std::vector<Point> corners;
    for (const auto& s : signs) corners.push_back(skew(s[0], s[1], s[2]));
    return corners;
}

std::vector<Point> tet_corners() {
    return {skew(0, 0, 0), skew(1, 0.1, 0), skew(0.2, 1, 0.05), skew(0.1, 0.15, 1)};
}

// A one-cell mesh of the given type, with node indices shuffled (reversed) so
// that the cell's node list is not simply 0..n-1.
Mesh one_cell_mesh(CellType type) {
    const bool tet = type == CellType::tet10;
    const std::vector<Point> local = tet ? quadratic_cell_nodes(tet_corners(), gmsh_tet10_edges)
                                         : quadratic_cell_nodes(hex_corners(), gmsh_hex20_edges);
    const int n = static_cast<int>(local.size());
    Mesh mesh;
    mesh.cell_type = type;
    mesh.nodes.resize(n);
    for (int a = 0; a < n; ++a) {
        mesh.nodes[n - 1 - a] = local[a];
        mesh.cells.push_back(n - 1 - a);
    }
    mesh.cell_part = {0};
    mesh.part_names = {"core"};
    mesh.node_groups["core_inner"] = {0, 2, 5};
    mesh.node_groups["core_outer"] = {1, 3};
    return mesh;
}

std::vector<Mode> fake_modes(int n_nodes) {
    std::vector<Mode> modes(2);
    for (int k = 0; k < 2; ++k) {
        Mode& mode = modes[k];
        mode.index = k + 1;
        mode.frequency_hz = k == 0 ? 0.0 : 48.8;
        mode.eigenvalue = std::pow(2 * M_PI * mode.frequency_hz, 2);
        mode.label.type = k == 0 ? "rigid" : "bending";
        mode.label.n = k;
        mode.label.m = 2 * k;
        mode.label.dominant_share = 0.5 + 0.25 * k;
        mode.relative_residual = 1e-12 * (k + 1);
        mode.effective_mass = {1.0 + k, 2.0 + k, 3.0 + k, 4.0 + k};
        for (int i = 0; i < 3 * n_nodes; ++i) mode.shape.push_back(0.001 * i + k);
    }
    return modes;
}

const std::string case_json = R"({"name": "tiny \"tube\"", "core": {"length": 0.5}})";

// ---------------------------------------------------------------- reading back

struct H5 {
    hid_t id;
    herr_t (*closer)(hid_t);
    ~H5() {
        if (id >= 0) closer(id);
    }
    operator hid_t() const { return id; }
};

std::vector<hsize_t> dims_of(hid_t dataset) {
    H5 space{H5Dget_space(dataset), H5Sclose};
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(std::max(rank, 0));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    return dims;
}

template <class T>
std::vector<T> read(hid_t file, const std::string& path, hid_t memory_type,
                    std::vector<hsize_t> expected_dims) {
    H5 set{H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose};
    REQUIRE(set.id >= 0);
    INFO(path);
    REQUIRE(dims_of(set) == expected_dims);
    hsize_t count = 1;
    for (hsize_t d : expected_dims) count *= d;
    std::vector<T> values(count);
    if (count > 0)
        REQUIRE(H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
    return values;
}

std::vector<double> read_doubles(hid_t f, const std::string& p, std::vector<hsize_t> dims) {
    return read<double>(f, p, H5T_NATIVE_DOUBLE, std::move(dims));
}
std::vector<std::int64_t> read_int64(hid_t f, const std::string& p, std::vector<hsize_t> dims) {
    return read<std::int64_t>(f, p, H5T_NATIVE_INT64, std::move(dims));
}
std::vector<std::int32_t> read_int32(hid_t f, const std::string& p, std::vector<hsize_t> dims) {
    return read<std::int32_t>(f, p, H5T_NATIVE_INT32, std::move(dims));
}

// The file types must be exactly the documented ones (python relies on them).
void check_file_type(hid_t file, const std::string& path, hid_t expected) {
    H5 set{H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose};
    H5 type{H5Dget_type(set), H5Tclose};
    INFO(path);
    CHECK(H5Tequal(type, expected) > 0);
}

std::vector<std::string> read_strings(hid_t file, const std::string& path) {
    H5 set{H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose};
    REQUIRE(set.id >= 0);
    H5 type{H5Dget_type(set), H5Tclose};
    REQUIRE(H5Tis_variable_str(type) > 0);
    H5 space{H5Dget_space(set), H5Sclose};
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    std::vector<char*> raw(n, nullptr);
    if (n > 0) REQUIRE(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) >= 0);
    std::vector<std::string> out(raw.begin(), raw.end());
    if (n > 0) H5Dvlen_reclaim(type, space, H5P_DEFAULT, raw.data());
    return out;
}

std::string read_string_attribute(hid_t object, const std::string& name) {
    H5 attribute{H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose};
    REQUIRE(attribute.id >= 0);
    H5 type{H5Aget_type(attribute), H5Tclose};
    REQUIRE(H5Tis_variable_str(type) > 0);
    char* raw = nullptr;
    REQUIRE(H5Aread(attribute, type, &raw) >= 0);
    std::string out = raw;
    H5free_memory(raw);
    return out;
}

int read_int_attribute(hid_t object, const std::string& name) {
    H5 attribute{H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose};
    REQUIRE(attribute.id >= 0);
    int value = -1;
    REQUIRE(H5Aread(attribute, H5T_NATIVE_INT, &value) >= 0);
    return value;
}

// Everything write_modes_h5 writes, compared with what went in.
void check_file_matches(const std::string& path, const Mesh& mesh,
                        const std::vector<Mode>& modes) {
    H5 file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    REQUIRE(file.id >= 0);
    const hsize_t N = mesh.n_nodes(), C = mesh.n_cells(), K = modes.size();
    const hsize_t per_cell = mesh.nodes_per_cell();

    CHECK(read_int_attribute(file, "schema_version") == 1);
    CHECK(read_string_attribute(file, "program") == "coremodal 9.9.9-test");
    CHECK(read_string_attribute(file, "case_name") == "tiny \"tube\"");
    CHECK(read_strings(file, "/case/json") == std::vector<std::string>{case_json});

    const std::vector<double> nodes = read_doubles(file, "/mesh/nodes", {N, 3});
    for (hsize_t a = 0; a < N; ++a)
        for (int c = 0; c < 3; ++c) CHECK(nodes[3 * a + c] == mesh.nodes[a][c]);
    check_file_type(file, "/mesh/nodes", H5T_IEEE_F64LE);

    const std::vector<std::int64_t> cells = read_int64(file, "/mesh/cells", {C, per_cell});
    CHECK(std::vector<std::int64_t>(mesh.cells.begin(), mesh.cells.end()) == cells);
    check_file_type(file, "/mesh/cells", H5T_STD_I64LE);
    {
        H5 cells_set{H5Dopen2(file, "/mesh/cells", H5P_DEFAULT), H5Dclose};
        CHECK(read_string_attribute(cells_set, "cell_type") == cell_type_name(mesh.cell_type));
    }
    const hsize_t vtk_per_cell = vtk_nodes_per_cell(mesh.cell_type);
    CHECK(read_int64(file, "/mesh/vtk_cells", {C, vtk_per_cell}) == vtk_cells(mesh));
    check_file_type(file, "/mesh/vtk_cells", H5T_STD_I64LE);

    CHECK(read_int32(file, "/mesh/cell_part", {C}) ==
          std::vector<std::int32_t>(mesh.cell_part.begin(), mesh.cell_part.end()));
    check_file_type(file, "/mesh/cell_part", H5T_STD_I32LE);
    CHECK(read_strings(file, "/mesh/part_names") == mesh.part_names);
    for (const auto& [name, group] : mesh.node_groups) {
        CHECK(read_int64(file, "/mesh/node_groups/" + name, {group.size()}) ==
              std::vector<std::int64_t>(group.begin(), group.end()));
    }

    std::vector<double> frequency, eigenvalue, residual, share, effective_mass;
    std::vector<std::int32_t> n, m;
    std::vector<std::string> type;
    for (const Mode& mode : modes) {
        frequency.push_back(mode.frequency_hz);
        eigenvalue.push_back(mode.eigenvalue);
        residual.push_back(mode.relative_residual);
        share.push_back(mode.label.dominant_share);
        n.push_back(mode.label.n);
        m.push_back(mode.label.m);
        type.push_back(mode.label.type);
        const EffectiveMass& e = mode.effective_mass;
        effective_mass.insert(effective_mass.end(), {e.x, e.y, e.z, e.rz});
    }
    CHECK(read_doubles(file, "/modes/frequency_hz", {K}) == frequency);
    CHECK(read_doubles(file, "/modes/eigenvalue", {K}) == eigenvalue);
    CHECK(read_doubles(file, "/modes/relative_residual", {K}) == residual);
    CHECK(read_doubles(file, "/modes/dominant_share", {K}) == share);
    CHECK(read_doubles(file, "/modes/effective_mass", {K, 4}) == effective_mass);
    CHECK(read_int32(file, "/modes/n", {K}) == n);
    CHECK(read_int32(file, "/modes/m", {K}) == m);
    check_file_type(file, "/modes/n", H5T_STD_I32LE);
    CHECK(read_strings(file, "/modes/type") == type);
    for (hsize_t k = 0; k < K; ++k) {
        const std::string name = modes_h5_shape_dataset(static_cast<int>(k) + 1);
        CHECK(read_doubles(file, name, {N, 3}) == modes[k].shape);
    }
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

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

TEST_CASE("write_modes_h5 writes every dataset of schema 1", "[output][h5]") {
    TempDir dir;
    for (CellType type : {CellType::hex20, CellType::tet10}) {
        INFO(cell_type_name(type));
        const Mesh mesh = one_cell_mesh(type);
        const std::vector<Mode> modes = fake_modes(mesh.n_nodes());
        const std::string path = dir.file(std::string("modes_") + cell_type_name(type) + ".h5");
        write_modes_h5(path, mesh, modes, "tiny \"tube\"", case_json, "9.9.9-test");
        check_file_matches(path, mesh, modes);
    }
}

TEST_CASE("write_modes_h5 handles a run with no modes and overwrites old files", "[output][h5]") {
    TempDir dir;
    const Mesh mesh = one_cell_mesh(CellType::hex20);
    const std::string path = dir.file("modes.h5");
    write_modes_h5(path, mesh, fake_modes(mesh.n_nodes()), "tiny", case_json, "coremodal 9.9.9-test");
    write_modes_h5(path, mesh, {}, "tiny \"tube\"", case_json, "coremodal 9.9.9-test");
    check_file_matches(path, mesh, {});
}

TEST_CASE("write_modes_h5 reports failures with the path", "[output][h5]") {
    TempDir dir;
    const Mesh mesh = one_cell_mesh(CellType::hex20);

    const std::string missing_dir = dir.file("no/such/dir/modes.h5");
    CHECK_THROWS_WITH(write_modes_h5(missing_dir, mesh, fake_modes(mesh.n_nodes()), "x", "{}", "1"),
                      Catch::Contains(missing_dir));

    // A shape of the wrong length is refused before any file is created.
    const std::string path = dir.file("bad.h5");
    std::vector<Mode> modes = fake_modes(mesh.n_nodes());
    modes[1].shape.pop_back();
    CHECK_THROWS_WITH(write_modes_h5(path, mesh, modes, "x", "{}", "1"),
                      Catch::Contains(path) && Catch::Contains("mode 2"));
    CHECK_FALSE(fs::exists(path));
}

TEST_CASE("mode attribute names in the XDMF file", "[output][xdmf]") {
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

TEST_CASE("write_modes_xdmf points at the datasets of modes.h5", "[output][xdmf]") {
    TempDir dir;
    for (CellType type : {CellType::hex20, CellType::tet10}) {
        const Mesh mesh = one_cell_mesh(type);
        const std::vector<Mode> modes = fake_modes(mesh.n_nodes());
        write_modes_h5(dir.file("modes.h5"), mesh, modes, "tiny", case_json, "1");
        const std::string xdmf = dir.file("modes.xdmf");
        write_modes_xdmf(xdmf, "modes.h5", mesh, modes);

        const std::string text = slurp(xdmf);
        const std::string n = std::to_string(mesh.n_nodes());
        CHECK_THAT(text, Catch::Contains(std::string("TopologyType=\"") +
                                         xdmf_topology_type(type) + "\""));
        CHECK_THAT(text, Catch::Contains("Dimensions=\"1 " +
                                         std::to_string(vtk_nodes_per_cell(type)) + "\""));
        CHECK_THAT(text, Catch::Contains("modes.h5:/mesh/vtk_cells"));
        CHECK_THAT(text, Catch::Contains("modes.h5:/mesh/nodes"));
        CHECK_THAT(text, Catch::Contains("Name=\"part\""));
        CHECK_THAT(text, Catch::Contains("Name=\"mode_01_0.00Hz_rigid_n0_m0\""));
        CHECK_THAT(text, Catch::Contains("Name=\"mode_02_48.80Hz_bending_n1_m2\""));
        CHECK_THAT(text, Catch::Contains("modes.h5:/modes/shapes/mode_0002"));

        // Well-formed XML, checked by an independent parser when one is at hand.
        if (fs::exists("/usr/bin/python3")) {
            const std::string command =
                "/usr/bin/python3 -c 'import sys, xml.etree.ElementTree as E; "
                "r = E.parse(sys.argv[1]).getroot(); "
                "sys.exit(0 if len(r.findall(\"./Domain/Grid/Attribute\")) == 3 else 1)' " +
                xdmf;
            CHECK(std::system(command.c_str()) == 0);
        }
    }
}

TEST_CASE("write_modes_xdmf reports an unwritable path", "[output][xdmf]") {
    TempDir dir;
    const Mesh mesh = one_cell_mesh(CellType::hex20);
    const std::string path = dir.file("no/such/dir/modes.xdmf");
    CHECK_THROWS_WITH(write_modes_xdmf(path, "modes.h5", mesh, {}), Catch::Contains(path));
}
