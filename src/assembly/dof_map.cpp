#include "assembly/dof_map.hpp"

namespace coremodal {

DofMap make_dof_map(int n_nodes, const std::vector<int>& eliminated_nodes) {
    std::vector<char> eliminated(n_nodes, 0);
    for (int n : eliminated_nodes) eliminated.at(n) = 1;
    DofMap map;
    map.node_first_dof.assign(n_nodes, -1);
    for (int n = 0; n < n_nodes; ++n)
        if (!eliminated[n]) map.node_first_dof[n] = 3 * map.n_free_nodes++;
    map.n_dofs = 3 * map.n_free_nodes;
    return map;
}

std::pair<int, int> owned_free_nodes(int n_free_nodes, int rank, int size) {
    const int base = n_free_nodes / size, extra = n_free_nodes % size;
    const int first = rank * base + std::min(rank, extra);
    return {first, first + base + (rank < extra ? 1 : 0)};
}

}  // namespace coremodal
