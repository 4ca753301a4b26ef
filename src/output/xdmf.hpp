// modes.xdmf: an XDMF 3 description of modes.h5 so that ParaView can open the
// results directly (Xdmf3ReaderS). The modes are a temporal collection: one
// grid per mode, time = mode number, so that ParaView's time slider steps
// through them and Warp By Vector (vector "displacement", scale from the
// field data "warp_scale") shows each. The XDMF file holds no numbers but the
// per-mode field data; every array is a dataset of modes.h5.
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

// Name of the grid (time step) of mode number `number` (1-based position in
// the mode list), e.g. "mode_01_48.80Hz_bending_n1_m0". The number is
// zero-padded to the width of n_modes (at least 2 digits) so that the names
// sort in frequency order.
std::string xdmf_mode_name(const Mode& mode, int number, int n_modes);

// Writes the XDMF file. `h5_filename_relative` is the HDF5 file name as seen
// from the directory of the XDMF file (normally "modes.h5"); the datasets it
// points to are those written by write_modes_h5. Each mode's grid holds
// the cell data "part", the point data "displacement" (vector), "u_r",
// "u_theta", "u_z" and the field data "mode", "frequency_hz", "n", "m",
// "warp_scale" (suggested_warp_scale) and "type" (character codes). With no
// modes, one plain grid of the mesh. Throws std::runtime_error naming the
// path if the file cannot be written.
void write_modes_xdmf(const std::string& xdmf_path, const std::string& h5_filename_relative,
                      const Mesh& mesh, const std::vector<Mode>& modes);

}  // namespace coremodal
