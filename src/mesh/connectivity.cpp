#include "mesh/connectivity.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace coremodal {
namespace {

// Union-find over nodes with path halving.
struct DisjointSets {
    std::vector<int> parent;
    explicit DisjointSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    }
    void join(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

std::vector<MeshComponent> connected_components(const Mesh& mesh, const std::vector<std::vector<int>>& links) {
    DisjointSets sets(mesh.n_nodes());
    for (const auto& link : links)
        for (size_t a = 1; a < link.size(); ++a) sets.join(link[0], link[a]);
    for (int c = 0; c < mesh.n_cells(); ++c)
        for (int a = 1; a < mesh.nodes_per_cell(); ++a) sets.join(mesh.cell(c)[0], mesh.cell(c)[a]);
    std::map<int, MeshComponent> by_root;
    for (int c = 0; c < mesh.n_cells(); ++c) {
        MeshComponent& comp = by_root[sets.find(mesh.cell(c)[0])];
        comp.cells.push_back(c);
        comp.part_names.push_back(mesh.cell_part[c]);
    }
    std::vector<MeshComponent> out;
    for (auto& [root, comp] : by_root) {
        std::sort(comp.part_names.begin(), comp.part_names.end());
        comp.part_names.erase(std::unique(comp.part_names.begin(), comp.part_names.end()), comp.part_names.end());
        out.push_back(std::move(comp));
    }
    return out;
}

std::vector<std::string> unheld_parts(const Mesh& mesh, const std::vector<int>& held_nodes,
                                      const std::vector<std::vector<int>>& links) {
    std::vector<std::string> sentences;
    if (held_nodes.empty()) return sentences;
    std::vector<char> held(mesh.n_nodes(), 0);
    for (int n : held_nodes) held[n] = 1;
    // A node outside every cell (a frame mass) holds what it is linked to.
    for (bool spread = true; spread;) {
        spread = false;
        for (const auto& link : links)
            if (std::any_of(link.begin(), link.end(), [&](int n) { return held[n]; }))
                for (int n : link)
                    if (!held[n]) held[n] = 1, spread = true;
    }
    for (const MeshComponent& comp : connected_components(mesh, links)) {
        const bool is_held = std::any_of(comp.cells.begin(), comp.cells.end(), [&](int c) {
            return std::any_of(mesh.cell(c), mesh.cell(c) + mesh.nodes_per_cell(), [&](int n) { return held[n]; });
        });
        if (is_held) continue;
        std::string names;
        for (int p : comp.part_names) names += (names.empty() ? "'" : ", '") + mesh.part_names[p] + "'";
        sentences.push_back("mesh part " + names + " (" + std::to_string(comp.cells.size()) +
                            " cells) is not connected to any clamp or bearing: it will show six rigid-body modes");
    }
    return sentences;
}

}  // namespace coremodal
