#include "assembly/dof_map.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

namespace coremodal {

DofMap make_dof_map(int n_nodes, const std::vector<int>& eliminated_nodes, const std::vector<NodeTie>& ties,
                    const std::vector<int>& node_order) {
    COREMODAL_ASSERT(node_order.empty() || int(node_order.size()) == n_nodes);
    std::vector<char> numbered(n_nodes, 1);
    for (int n : eliminated_nodes) numbered.at(n) = 0;
    for (const NodeTie& t : ties) numbered.at(t.node) = 0;
    DofMap map;
    map.node_first_dof.assign(n_nodes, -1);
    for (int k = 0; k < n_nodes; ++k) {
        const int n = node_order.empty() ? k : node_order[k];
        if (numbered[n]) map.node_first_dof[n] = 3 * map.n_free_nodes++;
    }
    // A tied node follows its master, eliminated with it if the master is held.
    for (const NodeTie& t : ties) {
        COREMODAL_ASSERT(numbered[t.master] || map.node_first_dof[t.master] < 0);
        map.node_first_dof[t.node] = map.node_first_dof.at(t.master);
    }
    map.n_dofs = 3 * map.n_free_nodes;
    return map;
}

std::vector<int> slab_node_order(const Mesh& mesh) {
    std::array<double, 3> low{}, high{};
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    for (const auto& x : mesh.nodes)
        for (int d = 0; d < 3; ++d) {
            low[d] = std::min(low[d], x[d]);
            high[d] = std::max(high[d], x[d]);
        }
    int axis = 0;
    for (int d = 1; d < 3; ++d)
        if (high[d] - low[d] > high[axis] - low[axis]) axis = d;
    std::vector<int> order(mesh.n_nodes());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return mesh.nodes[a][axis] < mesh.nodes[b][axis]; });
    return order;
}

std::pair<int, int> owned_free_nodes(int n_free_nodes, int rank, int size) {
    const int base = n_free_nodes / size, extra = n_free_nodes % size;
    const int first = rank * base + std::min(rank, extra);
    return {first, first + base + (rank < extra ? 1 : 0)};
}

}  // namespace coremodal
