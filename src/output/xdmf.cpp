#include "output/xdmf.hpp"

#include "output/mode_display.hpp"
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

std::string number_text(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// A field-data value (Center="Grid"): ParaView shows it in the Information
// panel and the spreadsheet's Field Data, per time step.
void field_value(std::ostream& x, const std::string& name, const char* number_type, int precision,
                 const std::string& values, size_t count = 1) {
    x << "        <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Grid\">\n"
      << "          <DataItem Dimensions=\"" << count << "\" NumberType=\"" << number_type
      << "\" Precision=\"" << precision << "\" Format=\"XML\">" << values << "</DataItem>\n"
      << "        </Attribute>\n";
}

// XDMF has no string data: a word goes as its character codes (ParaView
// reads them into a vtkCharArray; paraview_mode.py joins them again).
std::string char_codes(const std::string& word) {
    std::ostringstream out;
    for (size_t i = 0; i < word.size(); ++i)
        out << (i ? " " : "") << static_cast<int>(static_cast<unsigned char>(word[i]));
    return out.str();
}

// Topology, geometry and the cells' part: the same datasets for every grid.
void write_mesh_items(std::ostream& x, const std::string& h5, const Mesh& mesh) {
    const std::string n_nodes = std::to_string(mesh.n_nodes());
    const std::string n_cells = std::to_string(mesh.n_cells());
    x << "        <Topology TopologyType=\"" << xdmf_topology_type(mesh.cell_type)
      << "\" NumberOfElements=\"" << n_cells << "\">\n"
      << "          "
      << hdf_item(h5, "/mesh/vtk_cells", n_cells + " " + std::to_string(vtk_nodes_per_cell(mesh.cell_type)),
                  "Int", 8)
      << "\n        </Topology>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n"
      << "          " << hdf_item(h5, "/mesh/nodes", n_nodes + " 3", "Float", 8) << "\n"
      << "        </Geometry>\n"
      << "        <Attribute Name=\"part\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
      << "          " << hdf_item(h5, "/mesh/cell_part", n_cells, "Int", 4) << "\n"
      << "        </Attribute>\n";
}

// One time step: mode `number` on the shared mesh, its displacement vector,
// the same scaled for display, its cylindrical components and its numbers
// as field data.
void write_mode_grid(std::ostream& x, const std::string& h5, const Mesh& mesh, const Mode& mode, int number,
                     int n_modes) {
    const std::string n_nodes = std::to_string(mesh.n_nodes());
    char label[160];
    std::snprintf(label, sizeof label, "mode %d: %.2f Hz, %s, n=%d, m=%d", number, mode.frequency_hz,
                  mode.label.type.c_str(), mode.label.n, mode.label.m);
    x << "      <Grid Name=\"" << xml_escape(xdmf_mode_name(mode, number, n_modes))
      << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << number << "\"/>\n"
      << "        <Information Name=\"label\" Value=\"" << xml_escape(label) << "\"/>\n";
    write_mesh_items(x, h5, mesh);
    x << "        <Attribute Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\">\n"
      << "          " << hdf_item(h5, modes_h5_shape_dataset(number), n_nodes + " 3", "Float", 8) << "\n"
      << "        </Attribute>\n";
    // Scaled for display (modes.h5 /modes/display): Warp By Vector at scale 1.
    x << "        <Attribute Name=\"display_displacement\" AttributeType=\"Vector\" Center=\"Node\">\n"
      << "          " << hdf_item(h5, modes_h5_component_dataset("display", number), n_nodes + " 3", "Float", 4)
      << "\n        </Attribute>\n";
    for (const char* component : {"u_r", "u_theta", "u_z"})
        x << "        <Attribute Name=\"" << component << "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
          << "          " << hdf_item(h5, modes_h5_component_dataset(component, number), n_nodes, "Float", 4)
          << "\n        </Attribute>\n";
    field_value(x, "mode", "Int", 4, std::to_string(number));
    field_value(x, "frequency_hz", "Float", 8, number_text(mode.frequency_hz));
    field_value(x, "n", "Int", 4, std::to_string(mode.label.n));
    field_value(x, "m", "Int", 4, std::to_string(mode.label.m));
    field_value(x, "warp_scale", "Float", 8, number_text(suggested_warp_scale(mesh, mode.shape, mode.label.type)));
    const std::string type = sanitize_name(mode.label.type);
    field_value(x, "type", "Char", 1, char_codes(type), type.size());
    x << "      </Grid>\n";
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
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      << "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
      << "  <Domain>\n";
    if (modes.empty()) {
        // Nothing to step through: the mesh alone, as one grid.
        x << "    <Grid Name=\"core\" GridType=\"Uniform\">\n";
        write_mesh_items(x, h5_filename_relative, mesh);
        x << "    </Grid>\n";
    } else {
        x << "    <Grid Name=\"modes\" GridType=\"Collection\" CollectionType=\"Temporal\">\n"
          << "      <Information Name=\"Time\" Value=\"mode number (1-based, in order of "
             "frequency)\"/>\n";
        const int n_modes = static_cast<int>(modes.size());
        for (int i = 0; i < n_modes; ++i) write_mode_grid(x, h5_filename_relative, mesh, modes[i], i + 1, n_modes);
        x << "    </Grid>\n";
    }
    x << "  </Domain>\n"
      << "</Xdmf>\n";

    std::ofstream out(xdmf_path, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open " + xdmf_path + " for writing");
    out << x.str();
    out.close();
    if (!out) throw std::runtime_error("cannot write " + xdmf_path);
}

}  // namespace coremodal
