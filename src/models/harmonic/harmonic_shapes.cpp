#include "models/harmonic/harmonic_shapes.hpp"

#include <cmath>

namespace coremodal {

std::vector<int> frame_nodes_of(const Scene& scene, const Mesh& mesh) {
    std::vector<int> nodes;
    for (const ChuckSpec& chuck : scene.supports.chucks) {
        const auto it = mesh.node_groups.find("frame_" + chuck.name);
        nodes.push_back(it == mesh.node_groups.end() ? -1 : it->second.at(0));
    }
    return nodes;
}

std::vector<double> revolved_field(const RevolvedMesh& revolved, const HarmonicDofs& dofs, int n,
                                   const std::vector<double>& cos_values, const std::vector<double>& sin_values,
                                   const std::vector<int>& frame_nodes) {
    const bool has_sin = n > 0 && !sin_values.empty();
    const auto value = [&](const std::vector<double>& x, int component) {
        const int d = dofs.of_component[component];
        return d < 0 ? 0.0 : x[d];
    };
    std::vector<double> u(3 * static_cast<size_t>(revolved.mesh.n_nodes()), 0.0);
    for (size_t i = 0; i < revolved.section_node.size(); ++i) {
        const int s = revolved.section_node[i];
        const double theta = revolved.theta[i], a = n * theta;
        const double c = std::cos(a), sn = n == 0 ? 1.0 : std::sin(a);
        double ur = value(cos_values, 3 * s) * c, ut = -value(cos_values, 3 * s + 1) * sn,
               uz = value(cos_values, 3 * s + 2) * c;
        if (has_sin) {
            ur += value(sin_values, 3 * s) * sn;
            ut += value(sin_values, 3 * s + 1) * c;
            uz += value(sin_values, 3 * s + 2) * sn;
        }
        u[3 * i] = ur * std::cos(theta) - ut * std::sin(theta);
        u[3 * i + 1] = ur * std::sin(theta) + ut * std::cos(theta);
        u[3 * i + 2] = uz;
    }
    for (size_t f = 0; f < frame_nodes.size(); ++f) {
        const int d = dofs.frame[f];
        if (frame_nodes[f] < 0 || d < 0) continue;
        const size_t i = 3 * static_cast<size_t>(frame_nodes[f]);
        if (n == 1) {
            u[i] = cos_values[d];
            u[i + 1] = has_sin ? sin_values[d] : 0.0;
        } else {
            u[i + 2] = cos_values[d];
        }
    }
    return u;
}

}  // namespace coremodal
