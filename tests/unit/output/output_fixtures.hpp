// Shared fixtures of the modes.h5 and modes.xdmf tests: a one-cell mesh with
// a skewed geometry (so that a wrong node permutation cannot pass by
// symmetry), fake modes, a temporary directory and readers of HDF5 datasets.
#pragma once

#include "mesh/mesh.hpp"
#include "modes/mode_set.hpp"

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace coremodal::output_test {

namespace fs = std::filesystem;

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

inline Point midpoint(const Point& a, const Point& b) {
    return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

// A deliberately skewed trilinear map of the reference cube, so that no two
// distinct edges share a midpoint and a wrong permutation cannot pass by symmetry.
inline Point skew(double x, double y, double z) {
    return {1.0 + 0.9 * x + 0.1 * y + 0.05 * y * z, 2.0 + 1.3 * y + 0.2 * z + 0.07 * x * y,
            -0.5 + 0.7 * z + 0.15 * x + 0.03 * x * z};
}

// gmsh's hex20 edges, in the order of its edge nodes 8..19.
inline const std::vector<std::pair<int, int>> gmsh_hex20_edges = {
    {0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3}, {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
// VTK_QUADRATIC_HEXAHEDRON edges, in the order of its edge nodes 8..19.
inline const std::vector<std::pair<int, int>> vtk_hex20_edges = {
    {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
// gmsh's tet10 edges (nodes 4..9) and VTK_QUADRATIC_TETRA's.
inline const std::vector<std::pair<int, int>> gmsh_tet10_edges = {{0, 1}, {1, 2}, {2, 0},
                                                           {0, 3}, {2, 3}, {1, 3}};
inline const std::vector<std::pair<int, int>> vtk_tet10_edges = {{0, 1}, {1, 2}, {2, 0},
                                                          {0, 3}, {1, 3}, {2, 3}};

// Corners in gmsh order, then edge nodes at the midpoints of gmsh's edges.
inline std::vector<Point> quadratic_cell_nodes(const std::vector<Point>& corners,
                                        const std::vector<std::pair<int, int>>& gmsh_edges) {
    std::vector<Point> nodes = corners;
    for (auto [a, b] : gmsh_edges) nodes.push_back(midpoint(corners[a], corners[b]));
    return nodes;
}

inline std::vector<Point> hex_corners() {
    // gmsh (and VTK) corner order: bottom face counter-clockwise, then top.
    const int signs[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    std::vector<Point> corners;
    for (const auto& s : signs) corners.push_back(skew(s[0], s[1], s[2]));
    return corners;
}

inline std::vector<Point> tet_corners() {
    return {skew(0, 0, 0), skew(1, 0.1, 0), skew(0.2, 1, 0.05), skew(0.1, 0.15, 1)};
}

// A one-cell mesh of the given type, with node indices shuffled (reversed) so
// that the cell's node list is not simply 0..n-1.
inline Mesh one_cell_mesh(CellType type) {
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

inline std::vector<Mode> fake_modes(int n_nodes) {
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

inline const std::string case_json = R"({"name": "tiny \"tube\"", "core": {"length": 0.5}})";

// ---------------------------------------------------------------- reading back

struct H5 {
    hid_t id;
    herr_t (*closer)(hid_t);
    ~H5() {
        if (id >= 0) closer(id);
    }
    operator hid_t() const { return id; }
};

inline std::vector<hsize_t> dims_of(hid_t dataset) {
    H5 space{H5Dget_space(dataset), H5Sclose};
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(std::max(rank, 0));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    return dims;
}

template <class T>
inline std::vector<T> read(hid_t file, const std::string& path, hid_t memory_type,
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

inline std::vector<double> read_doubles(hid_t f, const std::string& p, std::vector<hsize_t> dims) {
    return read<double>(f, p, H5T_NATIVE_DOUBLE, std::move(dims));
}
inline std::vector<std::int64_t> read_int64(hid_t f, const std::string& p, std::vector<hsize_t> dims) {
    return read<std::int64_t>(f, p, H5T_NATIVE_INT64, std::move(dims));
}
inline std::vector<std::int32_t> read_int32(hid_t f, const std::string& p, std::vector<hsize_t> dims) {
    return read<std::int32_t>(f, p, H5T_NATIVE_INT32, std::move(dims));
}

// The file types must be exactly the documented ones (python relies on them).
inline void check_file_type(hid_t file, const std::string& path, hid_t expected) {
    H5 set{H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose};
    H5 type{H5Dget_type(set), H5Tclose};
    INFO(path);
    CHECK(H5Tequal(type, expected) > 0);
}

inline std::vector<std::string> read_strings(hid_t file, const std::string& path) {
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

inline std::string read_string_attribute(hid_t object, const std::string& name) {
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

inline int read_int_attribute(hid_t object, const std::string& name) {
    H5 attribute{H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose};
    REQUIRE(attribute.id >= 0);
    int value = -1;
    REQUIRE(H5Aread(attribute, H5T_NATIVE_INT, &value) >= 0);
    return value;
}

inline std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace coremodal::output_test
