// modes.xdmf: an XDMF 3 description of modes.h5 so that ParaView can open the
// results directly (Xdmf3 reader; pick a mode vector, then Warp By Vector).
// The XDMF file holds no numbers itself; it points into modes.h5.
//
// XDMF uses VTK node ordering for quadratic cells, which differs from gmsh's
// for the edge nodes, so modes.h5 also stores the cells in VTK order
// (/mesh/vtk_cells); the helpers below produce them.
#pragma once

#include "mesh/mesh.hpp"
#include "modes/mode_set.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace coremodal {

// Number of nodes of the VTK/XDMF cell used to show `type`: 20 for hex20 and
// hex27 (a hex27 is shown as a Hexahedron_20 from its first 20 nodes, which
// XDMF/ParaView handle everywhere), 10 for tet10.
int vtk_nodes_per_cell(CellType type);

// VTK node i of a cell is gmsh node vtk_node_order(type)[i] of that cell.
std::vector<int> vtk_node_order(CellType type);

// All cells of the mesh in VTK order, n_cells x vtk_nodes_per_cell, row-major.
std::vector<std::int64_t> vtk_cells(const Mesh& mesh);

// XDMF TopologyType: "Hexahedron_20" or "Tetrahedron_10".
const char* xdmf_topology_type(CellType type);

// Name of the node attribute holding mode number `number` (1-based position
// in the mode list), e.g. "mode_01_48.80Hz_bending_n1_m0". The number is
// zero-padded to the width of n_modes (at least 2 digits) so that the names
// sort in frequency order in ParaView's attribute list.
std::string xdmf_mode_name(const Mode& mode, int number, int n_modes);

// Writes the XDMF file. `h5_filename_relative` is the HDF5 file name as seen
// from the directory of the XDMF file (normally "modes.h5"); the datasets it
// points to are those written by write_modes_h5. Throws std::runtime_error
// naming the path if the file cannot be written.
void write_modes_xdmf(const std::string& xdmf_path, const std::string& h5_filename_relative,
                      const Mesh& mesh, const std::vector<Mode>& modes);

}  // namespace coremodal
