// modes.h5: write a tiny synthetic mesh with fake modes and read every
// dataset back with the HDF5 C API.
#include "output/mode_display.hpp"
#include "output/modes_h5.hpp"
#include "output/xdmf.hpp"
#include "unit/output/output_fixtures.hpp"

using namespace coremodal;
using namespace coremodal::output_test;

namespace {

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
    std::vector<double> warp_scale;
    for (const Mode& mode : modes) warp_scale.push_back(suggested_warp_scale(mesh, mode.shape, mode.label.type));
    CHECK(read_doubles(file, "/modes/warp_scale", {K}) == warp_scale);
    for (hsize_t k = 0; k < K; ++k) {
        const int number = static_cast<int>(k) + 1;
        CHECK(read_doubles(file, modes_h5_shape_dataset(number), {N, 3}) == modes[k].shape);
        // The cylindrical components are float32 copies of cylindrical_components.
        const CylindricalShape c = cylindrical_components(mesh, modes[k].shape);
        const std::pair<const char*, const std::vector<double>*> components[] = {
            {"u_r", &c.u_r}, {"u_theta", &c.u_theta}, {"u_z", &c.u_z}};
        for (const auto& [name, values] : components) {
            const std::string dataset = modes_h5_component_dataset(name, number);
            check_file_type(file, dataset, H5T_IEEE_F32LE);
            CHECK(read<float>(file, dataset, H5T_NATIVE_FLOAT, {N}) ==
                  std::vector<float>(values->begin(), values->end()));
        }
        // The display array: the shape times its warp scale, in float32, for ParaView at scale 1.
        const std::string display = modes_h5_component_dataset("display", number);
        check_file_type(file, display, H5T_IEEE_F32LE);
        std::vector<float> scaled;
        for (double u : modes[k].shape) scaled.push_back(static_cast<float>(warp_scale[k] * u));
        CHECK(read<float>(file, display, H5T_NATIVE_FLOAT, {N, 3}) == scaled);
    }
}

}  // namespace

// ---------------------------------------------------------------- tests

TEST_CASE("dataset names of the mode shapes and their cylindrical components", "[output][h5]") {
    CHECK(modes_h5_shape_dataset(7) == "/modes/shapes/mode_0007");
    CHECK(modes_h5_component_dataset("u_theta", 12) == "/modes/u_theta/mode_0012");
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

namespace {

// A tube's worth of nodes (structured: n_around x n_along) with one hex20 cell
// on the first 20 of them, and a bending-like mode: u_x = sin(pi z / L).
// Big enough for its node and shape datasets to be compressed.
Mesh tube_nodes_mesh(int n_around, int n_along, double length) {
    Mesh mesh = one_cell_mesh(CellType::hex20);
    for (int j = 0; j < n_along; ++j)
        for (int i = 0; i < n_around; ++i) {
            const double theta = 2 * M_PI * i / n_around;
            mesh.nodes.push_back({0.08 * std::cos(theta), 0.08 * std::sin(theta), length * j / (n_along - 1)});
        }
    return mesh;
}

bool has_deflate(hid_t file, const std::string& dataset) {
    H5 set{H5Dopen2(file, dataset.c_str(), H5P_DEFAULT), H5Dclose};
    H5 plist{H5Dget_create_plist(set), H5Pclose};
    for (int f = 0; f < H5Pget_nfilters(plist); ++f) {
        unsigned flags = 0, config = 0;
        size_t n_values = 0;
        if (H5Pget_filter2(plist, f, &flags, &n_values, nullptr, 0, nullptr, &config) == H5Z_FILTER_DEFLATE)
            return true;
    }
    return false;
}

}  // namespace

TEST_CASE("write_modes_h5 compresses large datasets and reads back every value", "[output][h5]") {
    TempDir dir;
    const double length = 2.0;
    const Mesh mesh = tube_nodes_mesh(32, 200, length);  // 6 420 nodes
    std::vector<Mode> modes = fake_modes(mesh.n_nodes());
    for (int a = 0; a < mesh.n_nodes(); ++a) {
        modes[1].shape[3 * a] = std::sin(M_PI * mesh.nodes[a][2] / length);
        modes[1].shape[3 * a + 1] = modes[1].shape[3 * a + 2] = 0;
    }
    const std::string path = dir.file("modes.h5");
    write_modes_h5(path, mesh, modes, "tiny \"tube\"", case_json, "coremodal 9.9.9-test");
    check_file_matches(path, mesh, modes);  // bit for bit, compressed or not

    H5 file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    const bool compressed = modes_h5_compression_available();
    INFO("deflate and shuffle available: " << compressed);
    for (const std::string dataset : {"/mesh/nodes", "/modes/shapes/mode_0002", "/modes/u_r/mode_0002"}) {
        INFO(dataset);
        CHECK(has_deflate(file, dataset) == compressed);
    }
    // Below kMinCompressedValues the filters would cost more than they save.
    CHECK_FALSE(has_deflate(file, "/modes/frequency_hz"));
    CHECK_FALSE(has_deflate(file, "/mesh/vtk_cells"));

    // Raw size of the node and shape datasets alone: 8 bytes per double
    // (nodes, 2 shapes) and 4 per float (2 x 3 cylindrical components).
    const double raw_bytes = mesh.n_nodes() * (3 * 8.0 * 3 + 2 * 3 * 4.0);
    const double file_bytes = static_cast<double>(fs::file_size(path));
    // Structured coordinates and smooth shapes shrink to well under half with
    // shuffle + gzip (23 % here); uncompressed, the file is at least the raw size.
    if (compressed)
        CHECK(file_bytes < 0.5 * raw_bytes);
    else
        CHECK(file_bytes > raw_bytes);
}
