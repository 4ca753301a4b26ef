// Degrees of freedom: three displacement components per node; nodes of a
// rigid clamp are eliminated (no penalty numbers in the matrices: they would
// create spurious eigenvalues and ruin the conditioning, deal.II step-36).
#pragma once

#include "mesh/mesh.hpp"

#include <vector>

namespace coremodal {

struct DofMap {
    std::vector<int> node_first_dof;  // 3 * (free node number), or -1 if eliminated
    int n_dofs = 0;
    int n_free_nodes = 0;

    // Global dof of component c of node, or -1 (ignored by PETSc's MatSetValues).
    int dof(int node, int c) const { return node_first_dof[node] < 0 ? -1 : node_first_dof[node] + c; }
};

// A node tied to another: it takes the other node's degrees of freedom (a
// bonded interface between facing core and chuck nodes; DESIGN.md: ties
// eliminate, no penalty numbers).
struct NodeTie {
    int node = 0, master = 0;
};

// Free nodes are numbered in `node_order` (every node once) when given,
// else in mesh order.
DofMap make_dof_map(int n_nodes, const std::vector<int>& eliminated_nodes, const std::vector<NodeTie>& ties = {},
                    const std::vector<int>& node_order = {});

// The nodes sorted along the longest side of the mesh's bounding box. The
// processes own contiguous blocks of free nodes (owned_free_nodes), so in
// this order each owns a slab and only the cells on a slab's face send
// entries to another process; in mesh order (gmsh numbers the cells'
// mid-side nodes after all corners) nearly every cell did, and assembling
// case 03 on two processes took longer than on one (issue 19).
std::vector<int> slab_node_order(const Mesh& mesh);

// Free nodes [first, last) owned by `rank` of `size`: contiguous, balanced blocks.
std::pair<int, int> owned_free_nodes(int n_free_nodes, int rank, int size);

}  // namespace coremodal
