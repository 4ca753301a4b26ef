#include "models/coupled/contact_layer.hpp"

#include "element/face.hpp"
#include "effects/support_effects.hpp"

#include <cmath>

namespace coremodal {
namespace {

// Quadratic 1D Lagrange functions on {-1, 1, 0} for a section edge (end, end, middle).
Eigen::Vector3d edge_values(double s) { return {s * (s - 1) / 2, s * (s + 1) / 2, 1 - s * s}; }
Eigen::Vector3d edge_derivatives(double s) { return {s - 0.5, s + 0.5, -2 * s}; }

// Below this share of the layer's total stiffness a coupling is round-off of
// one that vanishes exactly (a block pair of opposite parity about the arc's
// symmetry line: 1e-16 relative).
constexpr double kVanishingContactShare = 1e-12;

}  // namespace

std::vector<HarmonicContactPoint> contact_points(const Scene& scene, const SectionMesh& mesh) {
    std::vector<HarmonicContactPoint> out;
    std::vector<double> g, w;
    gauss_legendre(kContactGaussAlong, g, w);
    const SupportEffects effects = support_effects(scene);
    for (size_t k = 0; k < effects.chucks.size(); ++k) {
        if (!effects.chucks[k].one_sided) continue;
        const auto& edges = mesh.edge_groups.at("interface_" + effects.chucks[k].placement.chuck + "_core");
        for (size_t e = 0; e < edges.size(); ++e) {
            Eigen::Matrix<double, 3, 2> x;
            for (int p = 0; p < 3; ++p) x.row(p) << mesh.nodes[edges[e][p]][0], mesh.nodes[edges[e][p]][1];
            for (int i = 0; i < kContactGaussAlong; ++i) {
                const Eigen::Vector3d N = edge_values(g[i]);
                const double ds = (x.transpose() * edge_derivatives(g[i])).norm();
                const double r = N.dot(x.col(0)), z = N.dot(x.col(1));
                const double weight = w[i] * ds * r * 2 * M_PI / kContactPointsAround;
                for (int q = 0; q < kContactPointsAround; ++q) {
                    const double theta = 2 * M_PI * q / kContactPointsAround;
                    const Eigen::Vector3d at(r * std::cos(theta), r * std::sin(theta), z);
                    out.push_back({{static_cast<int>(k), at, weight}, static_cast<int>(e), N, q, theta});
                }
            }
        }
    }
    return out;
}

void ContactLayer::set_stiffness(std::vector<Eigen::Vector3d> k) {
    stiffness = std::move(k);
    weight_around.assign(kContactPointsAround, Eigen::Vector3d::Zero());
    for (size_t i = 0; i < points.size(); ++i) weight_around[points[i].around] += points[i].bore.area_weight * stiffness[i];
}

double contact_integral(const ContactLayer& layer, HarmonicFamily a, HarmonicFamily b, int component) {
    double sum = 0;
    for (int q = 0; q < kContactPointsAround; ++q) {
        const double k = layer.weight_around[q][component];
        if (k == 0) continue;
        const double theta = 2 * M_PI * q / kContactPointsAround;
        sum += k * trig_factor(a, component, theta) * trig_factor(b, component, theta);
    }
    return sum;
}

bool contact_couples(const ContactLayer& layer, HarmonicFamily a, HarmonicFamily b, int component) {
    double total = 0;
    for (const Eigen::Vector3d& k : layer.weight_around) total += k[component];
    return std::abs(contact_integral(layer, a, b, component)) > kVanishingContactShare * total;
}

bool contact_couples(const ContactLayer& layer, HarmonicFamily a, HarmonicFamily b) {
    for (int c = 0; c < 3; ++c)
        if (contact_couples(layer, a, b, c)) return true;
    return false;
}

Eigen::Matrix<double, 9, 9> contact_edge_matrix(const ContactLayer& layer, size_t first, size_t last,
                                                HarmonicFamily a, HarmonicFamily b) {
    Eigen::Matrix<double, 9, 9> K = Eigen::Matrix<double, 9, 9>::Zero();
    for (size_t i = first; i < last; ++i) {
        const Eigen::Vector3d& k = layer.stiffness[i];
        if (k.isZero(0)) continue;
        const HarmonicContactPoint& p = layer.points[i];
        Eigen::Vector3d s;  // w k_c t_c(a) t_c(b) per component
        for (int c = 0; c < 3; ++c)
            s[c] = p.bore.area_weight * k[c] * trig_factor(a, c, p.theta) * trig_factor(b, c, p.theta);
        for (int u = 0; u < 3; ++u)
            for (int v = 0; v < 3; ++v)
                for (int c = 0; c < 3; ++c) K(3 * u + c, 3 * v + c) += p.N[u] * p.N[v] * s[c];
    }
    return K;
}

}  // namespace coremodal
