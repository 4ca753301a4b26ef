#include "assembly/dof_map.hpp"

#include "common/error.hpp"

namespace coremodal {

DofMap make_dof_map(int n_nodes, const std::vector<int>& eliminated_nodes, const std::vector<NodeTie>& ties) {
    std::vector<char> numbered(n_nodes, 1);
    for (int n : eliminated_nodes) numbered.at(n) = 0;
    for (const NodeTie& t : ties) numbered.at(t.node) = 0;
    DofMap map;
    map.node_first_dof.assign(n_nodes, -1);
    for (int n = 0; n < n_nodes; ++n)
        if (numbered[n]) map.node_first_dof[n] = 3 * map.n_free_nodes++;
    // A tied node follows its master, eliminated with it if the master is held.
    for (const NodeTie& t : ties) {
        COREMODAL_ASSERT(numbered[t.master] || map.node_first_dof[t.master] < 0);
        map.node_first_dof[t.node] = map.node_first_dof.at(t.master);
    }
    map.n_dofs = 3 * map.n_free_nodes;
    return map;
}

std::pair<int, int> owned_free_nodes(int n_free_nodes, int rank, int size) {
    const int base = n_free_nodes / size, extra = n_free_nodes % size;
    const int first = rank * base + std::min(rank, extra);
    return {first, first + base + (rank < extra ? 1 : 0)};
}

}  // namespace coremodal
