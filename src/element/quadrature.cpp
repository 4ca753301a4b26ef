// Quadrature rules for the element kernels.
#include "element/quadrature.hpp"

#include <array>
#include <cmath>

namespace coremodal {

QuadratureRule gauss_hex_3x3x3() {
    const double a = std::sqrt(3.0 / 5.0);
    const std::array<double, 3> x{-a, 0.0, a};
    const std::array<double, 3> w{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    QuadratureRule rule;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                rule.points.emplace_back(x[i], x[j], x[k]);
                rule.weights.push_back(w[i] * w[j] * w[k]);
            }
    return rule;
}

namespace {

// Adds the 4 points with barycentric coordinates (a, a, a, 1 - 3a) permuted.
void add_vertex_orbit(QuadratureRule& rule, double a, double weight) {
    const double b = 1.0 - 3.0 * a;
    const std::array<Eigen::Vector3d, 4> points{Eigen::Vector3d(a, a, a), Eigen::Vector3d(b, a, a),
                                                Eigen::Vector3d(a, b, a), Eigen::Vector3d(a, a, b)};
    for (const auto& p : points) {
        rule.points.push_back(p);
        rule.weights.push_back(weight);
    }
}

// Adds the 6 points with barycentric coordinates (a, a, b, b), b = 1/2 - a, permuted.
void add_edge_orbit(QuadratureRule& rule, double a, double weight) {
    const double b = 0.5 - a;
    const std::array<Eigen::Vector3d, 6> points{
        Eigen::Vector3d(a, a, b), Eigen::Vector3d(a, b, a), Eigen::Vector3d(b, a, a),
        Eigen::Vector3d(b, b, a), Eigen::Vector3d(b, a, b), Eigen::Vector3d(a, b, b)};
    for (const auto& p : points) {
        rule.points.push_back(p);
        rule.weights.push_back(weight);
    }
}

}  // namespace

// Orbit parameters and weights re-solved from the moment equations to 25
// digits (the test checks every monomial of degree <= 5).
QuadratureRule tet_degree5_14_point() {
    QuadratureRule rule;
    add_vertex_orbit(rule, 0.3108859192633006153034097, 0.01878132095300265196431664);
    add_vertex_orbit(rule, 0.09273525031089124266349989, 0.01224884051939366294240825);
    add_edge_orbit(rule, 0.04550370412564957811779791, 0.007091003462846901173294516);
    return rule;
}

const QuadratureRule& full_integration_rule(CellType type) {
    static const QuadratureRule hex = gauss_hex_3x3x3();
    static const QuadratureRule tet = tet_degree5_14_point();
    return type == CellType::tet10 ? tet : hex;
}

}  // namespace coremodal
