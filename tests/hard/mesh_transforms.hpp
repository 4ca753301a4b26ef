// Meshes that describe the same body differently: renumbered nodes, turned
// about the axis. Hard-case tests solve both and compare.
#pragma once

#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace coremodal::testing {

// The same mesh with its nodes numbered in a random order.
inline Mesh shuffled(const Mesh& mesh, unsigned seed) {
    std::vector<int> new_of_old(mesh.n_nodes());
    std::iota(new_of_old.begin(), new_of_old.end(), 0);
    std::shuffle(new_of_old.begin(), new_of_old.end(), std::mt19937(seed));
    Mesh out = mesh;
    for (int old = 0; old < mesh.n_nodes(); ++old) out.nodes[new_of_old[old]] = mesh.nodes[old];
    for (int& v : out.cells) v = new_of_old[v];
    for (auto& [name, nodes] : out.node_groups) {
        for (int& v : nodes) v = new_of_old[v];
        std::sort(nodes.begin(), nodes.end());
    }
    for (auto& [name, set] : out.face_groups)
        for (int& v : set.faces) v = new_of_old[v];
    return out;
}

// The same mesh turned about the z axis.
inline Mesh rotated(const Mesh& mesh, double angle) {
    Mesh out = mesh;
    const double c = std::cos(angle), s = std::sin(angle);
    for (auto& x : out.nodes) x = {c * x[0] - s * x[1], s * x[0] + c * x[1], x[2]};
    return out;
}

}  // namespace coremodal::testing
