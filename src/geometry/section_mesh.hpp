// The r–z section of a tube-like scene meshed in 2D with 8-node serendipity
// quadrilaterals, for the axisymmetric-harmonic model level. Its nodes are
// those of the solid's hexahedra in one r–z plane (same layers, same graded
// axial segments), so the two levels differ only in how theta is treated.
// Chuck bodies and shafts are rectangles from the axis: [0, shaft radius]
// (split at the O-grid's square) and [shaft radius, body radius].
#pragma once

#include "geometry/tube_section.hpp"
#include "mesh/mesh.hpp"
#include "scene/scene.hpp"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace coremodal {

// A 3-node section edge: end nodes a, b and the middle node m.
using SectionEdge = std::array<int, 3>;

struct SectionMesh {
    std::vector<std::array<double, 2>> nodes;  // (r, z), metres
    std::vector<std::array<int, 8>> cells;     // quad8, gmsh order, xi along r, eta along z
    std::vector<int> cell_part;                // index into part_names
    std::vector<std::string> part_names;       // "core", "rest_paper", "chuck_left", "chuck_right"
    // Edges along z (ordered by z): "core_inner", "roll_outer" (the roll's
    // outer surface: the rest paper's, or the core's), "interface_<chuck>_core",
    // "interface_<chuck>_chuck" (the k-th edge faces the k-th core edge);
    // along r: "bearing_<chuck>" (the shaft end face).
    std::map<std::string, std::vector<SectionEdge>> edge_groups;
    // Node sets: "clamp_<name>" (bore nodes of a rigid clamp), "core_outer",
    // "axis" (r = 0).
    std::map<std::string, std::vector<int>> node_groups;
    int n_nodes() const { return static_cast<int>(nodes.size()); }
    int n_cells() const { return static_cast<int>(cells.size()); }
};

SectionMesh make_section_mesh(const TubeSection& section, const std::vector<ClampSpec>& clamps);

// The section turned about the axis into hex20 cells, n_around of them per
// section cell (cells at the axis are collapsed there: one node per axis
// node). For showing and naming the harmonic level's modes with the solid's
// tools (ParaView output, classifier, signatures); no solve uses it.
struct RevolvedMesh {
    Mesh mesh;                      // parts and node groups as the section's ("axis" aside)
    std::vector<int> section_node;  // per 3D node: the section node it turns from
    std::vector<double> theta;      // per 3D node: its angle, rad
};
RevolvedMesh revolve_section(const SectionMesh& section, int n_around);

}  // namespace coremodal
