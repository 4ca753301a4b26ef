// Which cells hang together: a part that shares no node with the clamped
// rest of the model is a mechanism (six rigid-body modes), and the user
// should hear which part it is before reading a table of zero frequencies.
#pragma once

#include "mesh/mesh.hpp"

#include <vector>

namespace coremodal {

struct MeshComponent {
    std::vector<int> cells;       // ascending
    std::vector<int> part_names;  // indices into Mesh::part_names, ascending, unique
};

// Connected components of the mesh (cells sharing a node are connected).
// `links` are further node sets that hang together (a spring layer's nodes, a
// tied pair): parts joined only through them are one component.
std::vector<MeshComponent> connected_components(const Mesh& mesh, const std::vector<std::vector<int>>& links = {});

// Sentences naming every component that holds none of `held_nodes`, e.g.
// "mesh part 'rest_paper' (120 cells) is not connected to any clamp: it will
// show six rigid-body modes". Empty when `held_nodes` is empty (a free scene).
std::vector<std::string> unheld_parts(const Mesh& mesh, const std::vector<int>& held_nodes,
                                      const std::vector<std::vector<int>>& links = {});

}  // namespace coremodal
