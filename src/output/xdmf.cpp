#include "output/xdmf.hpp"

#include "output/modes_h5.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace coremodal {

namespace {

// gmsh hex20 edge nodes 8..19 lie on the edges
//   8:(0,1) 9:(0,3) 10:(0,4) 11:(1,2) 12:(1,5) 13:(2,3)
//  14:(2,6) 15:(3,7) 16:(4,5) 17:(4,7) 18:(5,6) 19:(6,7);
// VTK_QUADRATIC_HEXAHEDRON wants its edge nodes 8..19 on
//   (0,1) (1,2) (2,3) (3,0) (4,5) (5,6) (6,7) (7,4) (0,4) (1,5) (2,6) (3,7).
// Corners 0..7 are numbered alike in both. So VTK node i is gmsh node:
constexpr int hex20_vtk_from_gmsh[20] = {0, 1, 2, 3, 4, 5, 6, 7,     //
                                         8, 11, 13, 9,               // bottom edges
                                         16, 18, 19, 17,             // top edges
                                         10, 12, 14, 15};            // vertical edges

// gmsh tet10 edge nodes 4..9 lie on (0,1) (1,2) (2,0) (0,3) (2,3) (1,3);
// VTK_QUADRATIC_TETRA wants (0,1) (1,2) (2,0) (0,3) (1,3) (2,3): the last two swap.
constexpr int tet10_vtk_from_gmsh[10] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};

std::string xml_escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

// Attribute names end up in ParaView menus and python expressions: keep them
// to letters, digits, '_', '.' and '-'.
std::string sanitize_name(const std::string& word) {
    std::string out = word;
    for (char& c : out) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
        if (!ok) c = '_';
    }
    return out;
}

// One <DataItem> pointing into the HDF5 file.
std::string hdf_item(const std::string& h5, const std::string& dataset, const std::string& dims,
                     const char* number_type, int precision) {
    std::ostringstream s;
    s << "<DataItem Dimensions=\"" << dims << "\" NumberType=\"" << number_type
      << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << xml_escape(h5) << ':'
      << dataset << "</DataItem>";
    return s.str();
}

}  // namespace

int vtk_nodes_per_cell(CellType type) { return type == CellType::tet10 ? 10 : 20; }

std::vector<int> vtk_node_order(CellType type) {
    if (type == CellType::tet10)
        return {std::begin(tet10_vtk_from_gmsh), std::end(tet10_vtk_from_gmsh)};
    // hex27 shares gmsh's hex20 numbering for its first 20 nodes.
    return {std::begin(hex20_vtk_from_gmsh), std::end(hex20_vtk_from_gmsh)};
}

std::vector<std::int64_t> vtk_cells(const Mesh& mesh) {
    const std::vector<int> order = vtk_node_order(mesh.cell_type);
    std::vector<std::int64_t> out;
    out.reserve(static_cast<size_t>(mesh.n_cells()) * order.size());
    for (int c = 0; c < mesh.n_cells(); ++c) {
        const int* cell = mesh.cell(c);
        for (int gmsh_node : order) out.push_back(cell[gmsh_node]);
    }
    return out;
}

const char* xdmf_topology_type(CellType type) {
    return type == CellType::tet10 ? "Tetrahedron_10" : "Hexahedron_20";
}

std::string xdmf_mode_name(const Mode& mode, int number, int n_modes) {
    const int width = std::max(2, static_cast<int>(std::to_string(std::max(n_modes, 1)).size()));
    std::string digits = std::to_string(number);
    if (static_cast<int>(digits.size()) < width) digits.insert(0, width - digits.size(), '0');
    char freq[64];
    std::snprintf(freq, sizeof freq, "%.2f", mode.frequency_hz);
    std::string f = freq;
    if (f == "-0.00") f = "0.00";  // a rigid mode's round-off, not a real sign
    return "mode_" + digits + "_" + f + "Hz_" + sanitize_name(mode.label.type) + "_n" +
           std::to_string(mode.label.n) + "_m" + std::to_string(mode.label.m);
}

void write_modes_xdmf(const std::string& xdmf_path, const std::string& h5_filename_relative,
                      const Mesh& mesh, const std::vector<Mode>& modes) {
    const std::string n_nodes = std::to_string(mesh.n_nodes());
    const std::string n_cells = std::to_string(mesh.n_cells());
    const std::string& h5 = h5_filename_relative;

    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      << "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"core\" GridType=\"Uniform\">\n"
      << "      <Topology TopologyType=\"" << xdmf_topology_type(mesh.cell_type)
      << "\" NumberOfElements=\"" << n_cells << "\">\n"
      << "        "
      << hdf_item(h5, "/mesh/vtk_cells",
                  n_cells + " " + std::to_string(vtk_nodes_per_cell(mesh.cell_type)), "Int", 8)
      << "\n      </Topology>\n"
      << "      <Geometry GeometryType=\"XYZ\">\n"
      << "        " << hdf_item(h5, "/mesh/nodes", n_nodes + " 3", "Float", 8) << "\n"
      << "      </Geometry>\n"
      << "      <Attribute Name=\"part\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
      << "        " << hdf_item(h5, "/mesh/cell_part", n_cells, "Int", 4) << "\n"
      << "      </Attribute>\n";
    const int n_modes = static_cast<int>(modes.size());
    for (int i = 0; i < n_modes; ++i) {
        x << "      <Attribute Name=\"" << xml_escape(xdmf_mode_name(modes[i], i + 1, n_modes))
          << "\" AttributeType=\"Vector\" Center=\"Node\">\n"
          << "        " << hdf_item(h5, modes_h5_shape_dataset(i + 1), n_nodes + " 3", "Float", 8)
          << "\n      </Attribute>\n";
    }
    x << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";

    std::ofstream out(xdmf_path, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open " + xdmf_path + " for writing");
    out << x.str();
    out.close();
    if (!out) throw std::runtime_error("cannot write " + xdmf_path);
}

}  // namespace coremodal
