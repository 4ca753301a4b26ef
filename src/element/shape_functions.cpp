// Shape functions of hex20, hex27 and tet10 in gmsh node ordering.
//
// Each function is written once for a generic node, from that node's
// reference coordinates, so the gmsh node table below is the only place the
// ordering lives; the unit tests check N_a(xi_b) = delta_ab on it.
#include "element/shape_functions.hpp"

#include <array>
#include <cmath>

namespace coremodal {

namespace {

// gmsh localNodeCoord for type 12 (hex27); its first 20 rows are type 17 (hex20).
// Corners 0-7, edge nodes 8-19 on edges (0,1),(0,3),(0,4),(1,2),(1,5),(2,3),
// (2,6),(3,7),(4,5),(4,7),(5,6),(6,7), face nodes 20-25, centre 26.
constexpr double hex27_nodes[27][3] = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
    {-1, 1, 1},   {0, -1, -1}, {-1, 0, -1}, {-1, -1, 0}, {1, 0, -1},  {1, -1, 0}, {0, 1, -1},
    {1, 1, 0},    {-1, 1, 0},  {0, -1, 1},  {-1, 0, 1},  {1, 0, 1},   {0, 1, 1},  {0, 0, -1},
    {0, -1, 0},   {-1, 0, 0},  {1, 0, 0},   {0, 1, 0},   {0, 0, 1},   {0, 0, 0}};

// gmsh localNodeCoord for type 11 (tet10): corners 0-3, then edge nodes on
// edges (0,1),(1,2),(2,0),(0,3),(2,3),(1,3).
constexpr double tet10_nodes[10][3] = {{0, 0, 0},     {1, 0, 0},     {0, 1, 0},   {0, 0, 1},
                                       {0.5, 0, 0},   {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5},
                                       {0, 0.5, 0.5}, {0.5, 0, 0.5}};
constexpr int tet10_edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {2, 3}, {1, 3}};

ReferenceCoords table(const double (*rows)[3], int n) {
    ReferenceCoords coords(n, 3);
    for (int a = 0; a < n; ++a)
        for (int j = 0; j < 3; ++j) coords(a, j) = rows[a][j];
    return coords;
}

struct ValueAndGradient {
    double value;
    Eigen::RowVector3d gradient;
};

// hex20 serendipity functions. Corner (c = +-1 in every direction):
//   N = 1/8 (1 + xi c_x)(1 + eta c_y)(1 + zeta c_z)(xi c_x + eta c_y + zeta c_z - 2);
// edge node with c_j = 0 in exactly one direction j:
//   N = (1 - xi_j^2) prod_{k != j} (1 + xi_k c_k) / 2.
ValueAndGradient hex20_function(const Eigen::Vector3d& xi, const double* c) {
    ValueAndGradient f{};
    const bool corner = c[0] != 0 && c[1] != 0 && c[2] != 0;
    if (corner) {
        std::array<double, 3> linear{};
        for (int j = 0; j < 3; ++j) linear[j] = 1.0 + xi[j] * c[j];
        const double s = xi[0] * c[0] + xi[1] * c[1] + xi[2] * c[2] - 2.0;
        f.value = linear[0] * linear[1] * linear[2] * s / 8.0;
        // d/dxi_j: c_j * (other two linear factors) * (s + linear_j) / 8
        for (int j = 0; j < 3; ++j) {
            const double others = linear[(j + 1) % 3] * linear[(j + 2) % 3];
            f.gradient[j] = c[j] * others * (s + linear[j]) / 8.0;
        }
        return f;
    }
    std::array<double, 3> factor{}, derivative{};
    for (int j = 0; j < 3; ++j) {
        if (c[j] == 0) {
            factor[j] = 1.0 - xi[j] * xi[j];
            derivative[j] = -2.0 * xi[j];
        } else {
            factor[j] = 0.5 * (1.0 + xi[j] * c[j]);
            derivative[j] = 0.5 * c[j];
        }
    }
    f.value = factor[0] * factor[1] * factor[2];
    for (int j = 0; j < 3; ++j)
        f.gradient[j] = derivative[j] * factor[(j + 1) % 3] * factor[(j + 2) % 3];
    return f;
}

// hex27: tensor product of 1D quadratic Lagrange functions.
ValueAndGradient hex27_function(const Eigen::Vector3d& xi, const double* c) {
    std::array<double, 3> factor{}, derivative{};
    for (int j = 0; j < 3; ++j) lagrange_1d(xi[j], c[j], factor[j], derivative[j]);
    ValueAndGradient f{};
    f.value = factor[0] * factor[1] * factor[2];
    for (int j = 0; j < 3; ++j)
        f.gradient[j] = derivative[j] * factor[(j + 1) % 3] * factor[(j + 2) % 3];
    return f;
}

// tet10 in barycentric coordinates L = (1 - xi - eta - zeta, xi, eta, zeta):
// corner i: L_i (2 L_i - 1); edge (i, j): 4 L_i L_j.
void tet10_functions(const Eigen::Vector3d& xi, Eigen::VectorXd* N,
                     Eigen::Matrix<double, Eigen::Dynamic, 3>* dN) {
    const std::array<double, 4> L{1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
    Eigen::Matrix<double, 4, 3> dL;
    dL << -1, -1, -1,  //
        1, 0, 0,       //
        0, 1, 0,       //
        0, 0, 1;
    for (int i = 0; i < 4; ++i) {
        if (N) (*N)(i) = L[i] * (2.0 * L[i] - 1.0);
        if (dN) dN->row(i) = (4.0 * L[i] - 1.0) * dL.row(i);
    }
    for (int e = 0; e < 6; ++e) {
        const int i = tet10_edges[e][0], j = tet10_edges[e][1];
        if (N) (*N)(4 + e) = 4.0 * L[i] * L[j];
        if (dN) dN->row(4 + e) = 4.0 * (L[j] * dL.row(i) + L[i] * dL.row(j));
    }
}

ValueAndGradient hex_function(CellType type, const Eigen::Vector3d& xi, int a) {
    const double* c = hex27_nodes[a];
    return type == CellType::hex20 ? hex20_function(xi, c) : hex27_function(xi, c);
}

}  // namespace

const ReferenceCoords& reference_node_coords(CellType type) {
    static const ReferenceCoords hex20 = table(hex27_nodes, 20);
    static const ReferenceCoords hex27 = table(hex27_nodes, 27);
    static const ReferenceCoords tet10 = table(tet10_nodes, 10);
    switch (type) {
        case CellType::hex20: return hex20;
        case CellType::hex27: return hex27;
        case CellType::tet10: return tet10;
    }
    return hex20;  // unreachable: all enumerators handled above
}

Eigen::VectorXd shape_values(CellType type, const Eigen::Vector3d& xi) {
    const int n = nodes_per_cell(type);
    Eigen::VectorXd N(n);
    if (type == CellType::tet10) {
        tet10_functions(xi, &N, nullptr);
        return N;
    }
    for (int a = 0; a < n; ++a) N(a) = hex_function(type, xi, a).value;
    return N;
}

Eigen::Matrix<double, Eigen::Dynamic, 3> shape_gradients(CellType type, const Eigen::Vector3d& xi) {
    const int n = nodes_per_cell(type);
    Eigen::Matrix<double, Eigen::Dynamic, 3> dN(n, 3);
    if (type == CellType::tet10) {
        tet10_functions(xi, nullptr, &dN);
        return dN;
    }
    for (int a = 0; a < n; ++a) dN.row(a) = hex_function(type, xi, a).gradient;
    return dN;
}

// 1D quadratic Lagrange function on nodes {-1, 0, 1} for the node at c.
void lagrange_1d(double x, double c, double& value, double& derivative) {
    if (c < 0) {
        value = 0.5 * x * (x - 1.0);
        derivative = x - 0.5;
    } else if (c > 0) {
        value = 0.5 * x * (x + 1.0);
        derivative = x + 0.5;
    } else {
        value = 1.0 - x * x;
        derivative = -2.0 * x;
    }
}

}  // namespace coremodal
