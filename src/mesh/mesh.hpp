// The mesh as the rest of the pipeline sees it: plain arrays, no gmsh.
#pragma once

#include "element/element.hpp"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace coremodal {

// Quadratic quadrilateral faces of a physical surface (gmsh order: corners,
// then mid-edges, then the centre for 9-node faces).
struct FaceSet {
    int nodes_per_face = 8;  // 8 or 9
    std::vector<int> faces;  // n_faces x nodes_per_face, 0-based mesh nodes
    int n_faces() const { return static_cast<int>(faces.size()) / nodes_per_face; }
    const int* face(int f) const { return faces.data() + static_cast<size_t>(f) * nodes_per_face; }
};

struct Mesh {
    CellType cell_type = CellType::hex20;
    std::vector<std::array<double, 3>> nodes;  // metres
    std::vector<int> cells;                    // n_cells x nodes_per_cell, gmsh order, 0-based
    std::vector<int> cell_part;                // per cell: index into part_names
    std::vector<std::string> part_names;       // physical volume names: "core", "rest_paper"
    // Physical surface groups as node sets (sorted, unique): "core_inner",
    // "core_outer", "clamp_left", "clamp_right", ...
    std::map<std::string, std::vector<int>> node_groups;
    // The same physical surfaces as quadratic quadrilateral faces, where they
    // are made of them (generated meshes): spring layers and bearings integrate over them.
    std::map<std::string, FaceSet> face_groups;

    int n_nodes() const { return static_cast<int>(nodes.size()); }
    int n_cells() const { return static_cast<int>(cell_part.size()); }
    int nodes_per_cell() const { return coremodal::nodes_per_cell(cell_type); }
    const int* cell(int c) const { return cells.data() + static_cast<size_t>(c) * nodes_per_cell(); }
};

}  // namespace coremodal
