// Element stiffness and consistent mass for quadratic solid cells (and, for a
// spinning scene, the gyroscopic matrix: element.hpp, element_gyroscopic).
//
// Weak form (linear elasticity, small strain), per cell Ve:
//   K_e = int_Ve B^T C(x) B dV,   M_e = int_Ve rho N^T N dV,
// where C(x) = rotate_to_global(C_cylindrical, theta(x)) with theta the polar
// angle of the integration point about the z axis: the material is
// orthotropic in (r, theta, z), so its global stiffness turns with the point.
//
// Cost (this runs ~40 000 times for a 500 000-DOF model): B is sparse, with
// node block B_a (6x3) holding only the three gradient components g_a. We form
// E = B^T (w detJ C) once per point (3n x 6) and add to column 3a+c of K the
// three columns of E that B_a's column c selects -- contiguous axpys over the
// upper triangle only, mirrored at the end. Mass is the scalar matrix
// rho N_a N_b detJ w, expanded by the 3x3 identity.
#include "element/element.hpp"

#include "common/error.hpp"
#include "element/quadrature.hpp"
#include "element/shape_functions.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace coremodal {

int nodes_per_cell(CellType type) {
    switch (type) {
        case CellType::hex20: return 20;
        case CellType::hex27: return 27;
        case CellType::tet10: return 10;
    }
    return 0;  // unreachable: all enumerators handled above
}

const char* cell_type_name(CellType type) {
    switch (type) {
        case CellType::hex20: return "hex20";
        case CellType::hex27: return "hex27";
        case CellType::tet10: return "tet10";
    }
    return "unknown";  // unreachable
}

namespace {

// Shape function values and reference gradients at every integration point of
// the full rule, with the node count N fixed at compile time so the per-point
// algebra uses fixed-size Eigen types.
template <int N>
struct ReferenceTables {
    std::vector<Eigen::Matrix<double, N, 1>> values;
    std::vector<Eigen::Matrix<double, N, 3>> gradients;
    std::vector<double> weights;
    std::vector<Eigen::Vector3d> points;
};

template <int N>
ReferenceTables<N> build_tables(CellType type) {
    const QuadratureRule& rule = full_integration_rule(type);
    ReferenceTables<N> tables;
    for (int q = 0; q < rule.size(); ++q) {
        tables.values.push_back(shape_values(type, rule.points[q]));
        tables.gradients.push_back(shape_gradients(type, rule.points[q]));
    }
    tables.weights = rule.weights;
    tables.points = rule.points;
    return tables;
}

template <int N>
const ReferenceTables<N>& reference_tables(CellType type);

template <>
const ReferenceTables<20>& reference_tables<20>(CellType) {
    static const ReferenceTables<20> tables = build_tables<20>(CellType::hex20);
    return tables;
}
template <>
const ReferenceTables<27>& reference_tables<27>(CellType) {
    static const ReferenceTables<27> tables = build_tables<27>(CellType::hex27);
    return tables;
}
template <>
const ReferenceTables<10>& reference_tables<10>(CellType) {
    static const ReferenceTables<10> tables = build_tables<10>(CellType::tet10);
    return tables;
}

[[noreturn]] void throw_bad_jacobian(CellType type, int q, int n_points, double det,
                                     const Eigen::Vector3d& xi) {
    std::ostringstream msg;
    msg << cell_type_name(type) << " cell: Jacobian determinant " << det
        << " <= 0 at integration point " << q + 1 << " of " << n_points
        << " (reference coordinates " << xi.transpose()
        << "); the cell is inverted or badly distorted (check node order and curved-edge "
           "node positions)";
    throw std::runtime_error(msg.str());
}

// Jacobian J(i, j) = d x_i / d xi_j at point q; throws unless det J > 0.
template <int N>
Eigen::Matrix3d checked_jacobian(CellType type, const ReferenceTables<N>& ref,
                                 const Eigen::Matrix<double, N, 3>& X, int q, double& det) {
    const Eigen::Matrix3d J = X.transpose().lazyProduct(ref.gradients[q]);
    det = J.determinant();
    if (!(det > 0)) throw_bad_jacobian(type, q, static_cast<int>(ref.weights.size()), det,
                                       ref.points[q]);
    return J;
}

template <int N>
void check_coords(CellType type, const CellCoords& coords) {
    COREMODAL_ASSERT(coords.rows() == N);
}

// Packed SIMD lanes (GCC/Clang vector extension). The stiffness update below
// is a sum of axpys over contiguous columns; with explicit lanes it compiles
// to packed arithmetic at plain -O2 (GCC's -O2 cost model does not vectorise
// loops of run-time length, and Eigen's fixed-size blocks are not inlined at
// -O2). One lane group is one hardware register: wider lanes than the
// register only add spills (measured: 4 lanes on SSE2 were slower than 2).
#ifdef __AVX__
constexpr int lane_count = 4;
#else
constexpr int lane_count = 2;
#endif
using Lanes = double __attribute__((vector_size(lane_count * sizeof(double))));

inline Lanes broadcast(double value) { return Lanes{} + value; }

constexpr int padded_rows(int n_dof) { return (n_dof + lane_count - 1) / lane_count * lane_count; }

// Per-cell accumulator for the upper triangle of K (3N x 3N), stored column by
// column with the leading dimension padded to whole lanes, so every column
// starts on a lane boundary and rows past 3N are harmless padding.
template <int N>
struct StiffnessAccumulator {
    static constexpr int n_dof = 3 * N;
    static constexpr int ld = padded_rows(n_dof);
    static constexpr int lanes_per_column = ld / lane_count;
    alignas(sizeof(Lanes)) double K[n_dof * ld];
    alignas(sizeof(Lanes)) double E[6 * ld];  // E = B^T Cw, column k at E + k*ld

    StiffnessAccumulator() {
        std::fill(std::begin(K), std::end(K), 0.0);
        std::fill(std::begin(E), std::end(E), 0.0);  // padding rows stay zero
    }

    const Lanes* E_col(int k) const { return reinterpret_cast<const Lanes*>(E + k * ld); }
    Lanes* K_col(int j) { return reinterpret_cast<Lanes*>(K + j * ld); }

    // E = B^T Cw (3N x 6), node by node. B_a^T has rows
    //   x: (g0, 0, 0, 0, g2, g1)   y: (0, g1, 0, g2, 0, g0)   z: (0, 0, g2, g1, g0, 0)
    // for Voigt (xx, yy, zz, yz, xz, xy) with engineering shears; Cw is
    // symmetric, so Cw(i, k) = Cw(k, i).
    void set_strain_stress_product(const Eigen::Matrix<double, N, 3>& G, const Matrix6& Cw) {
        for (int a = 0; a < N; ++a) {
            const double g0 = G(a, 0), g1 = G(a, 1), g2 = G(a, 2);
            for (int k = 0; k < 6; ++k) {
                double* column = E + k * ld + 3 * a;
                column[0] = g0 * Cw(0, k) + g2 * Cw(4, k) + g1 * Cw(5, k);
                column[1] = g1 * Cw(1, k) + g2 * Cw(3, k) + g0 * Cw(5, k);
                column[2] = g2 * Cw(2, k) + g1 * Cw(3, k) + g0 * Cw(4, k);
            }
        }
    }

    // Upper triangle of K += E B. Column 3a+c of B has three non-zeros, so
    // column 3a+c of K gains three columns of E; rows 0..3a+2 suffice (the
    // few below-diagonal rows of node a's block are ignored when stored).
    void add_stiffness_upper(const Eigen::Matrix<double, N, 3>& G) {
        const Lanes* e0 = E_col(0); const Lanes* e1 = E_col(1); const Lanes* e2 = E_col(2);
        const Lanes* e3 = E_col(3); const Lanes* e4 = E_col(4); const Lanes* e5 = E_col(5);
        for (int a = 0; a < N; ++a) {
            const Lanes g0 = broadcast(G(a, 0)), g1 = broadcast(G(a, 1)), g2 = broadcast(G(a, 2));
            Lanes* kx = K_col(3 * a);
            Lanes* ky = K_col(3 * a + 1);
            Lanes* kz = K_col(3 * a + 2);
            const int n_lanes = (3 * a + 3 + lane_count - 1) / lane_count;
            for (int p = 0; p < n_lanes; ++p) {
                kx[p] += g0 * e0[p] + g2 * e4[p] + g1 * e5[p];
                ky[p] += g1 * e1[p] + g2 * e3[p] + g0 * e5[p];
                kz[p] += g2 * e2[p] + g1 * e3[p] + g0 * e4[p];
            }
        }
    }

    // Mirrors the upper triangle into both triangles of the output.
    void store_symmetric(Eigen::MatrixXd& K_out) const {
        K_out.resize(n_dof, n_dof);
        for (int j = 0; j < n_dof; ++j)
            for (int i = 0; i <= j; ++i) K_out(i, j) = K_out(j, i) = K[j * ld + i];
    }
};

// Upper triangle of the scalar mass matrix: m_ab += s N_a N_b.
template <int N>
void add_mass_upper(const Eigen::Matrix<double, N, 1>& shape, double s,
                    Eigen::Matrix<double, N, N>& m) {
    for (int b = 0; b < N; ++b) {
        const double sb = s * shape(b);
        for (int a = 0; a <= b; ++a) m(a, b) += sb * shape(a);
    }
}

// M = m (x) I3 in node-major DOF order, from the upper triangle of m.
template <int N>
void expand_mass(const Eigen::Matrix<double, N, N>& m, Eigen::MatrixXd& M) {
    M.setZero(3 * N, 3 * N);
    for (int b = 0; b < N; ++b)
        for (int a = 0; a <= b; ++a)
            for (int c = 0; c < 3; ++c) M(3 * a + c, 3 * b + c) = M(3 * b + c, 3 * a + c) = m(a, b);
}

template <int N>
void integrate_cell(CellType type, const CellCoords& coords, const Matrix6& C_cylindrical,
                    double density, Eigen::MatrixXd& K, Eigen::MatrixXd& M) {
    check_coords<N>(type, coords);
    const ReferenceTables<N>& ref = reference_tables<N>(type);
    const Eigen::Matrix<double, N, 3> X = coords;
    // About 60 kB on the stack for hex27: no heap allocation per cell.
    StiffnessAccumulator<N> stiffness;
    Eigen::Matrix<double, N, N> m = Eigen::Matrix<double, N, N>::Zero();
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
        double det = 0;
        const Eigen::Matrix3d J = checked_jacobian<N>(type, ref, X, static_cast<int>(q), det);
        const double w_det = ref.weights[q] * det;
        // Physical gradients dN/dx = dN/dxi J^-1 (lazyProduct: small products
        // coefficient by coefficient rather than through Eigen's GEMM).
        const Eigen::Matrix<double, N, 3> G = ref.gradients[q].lazyProduct(J.inverse().eval());
        // Polar angle of the integration point; atan2(0, 0) = 0 on the axis,
        // where only isotropic (chuck) material is expected.
        const Eigen::Vector3d x = X.transpose().lazyProduct(ref.values[q]);
        const Matrix6 Cw = rotate_to_global(C_cylindrical, std::atan2(x.y(), x.x())) * w_det;
        stiffness.set_strain_stress_product(G, Cw);
        stiffness.add_stiffness_upper(G);
        add_mass_upper<N>(ref.values[q], density * w_det, m);
    }
    stiffness.store_symmetric(K);
    expand_mass<N>(m, M);
}

// G_e = (c - c^T) (x) I3 with c_ab = int rho N_a dN_b/dtheta dV (header).
template <int N>
Eigen::MatrixXd integrate_gyroscopic(CellType type, const CellCoords& coords, double density) {
    check_coords<N>(type, coords);
    const ReferenceTables<N>& ref = reference_tables<N>(type);
    const Eigen::Matrix<double, N, 3> X = coords;
    Eigen::Matrix<double, N, N> c = Eigen::Matrix<double, N, N>::Zero();
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
        double det = 0;
        const Eigen::Matrix3d J = checked_jacobian<N>(type, ref, X, static_cast<int>(q), det);
        const Eigen::Matrix<double, N, 3> G = ref.gradients[q].lazyProduct(J.inverse().eval());
        const Eigen::Vector3d x = X.transpose().lazyProduct(ref.values[q]);
        const Eigen::Matrix<double, N, 1> d_theta = x.x() * G.col(1) - x.y() * G.col(0);
        c.noalias() += (density * ref.weights[q] * det) * ref.values[q] * d_theta.transpose();
    }
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(3 * N, 3 * N);
    for (int b = 0; b < N; ++b)
        for (int a = 0; a < N; ++a)
            for (int k = 0; k < 3; ++k) out(3 * a + k, 3 * b + k) = c(a, b) - c(b, a);
    return out;
}

template <int N>
double integrate_volume(CellType type, const CellCoords& coords) {
    check_coords<N>(type, coords);
    const ReferenceTables<N>& ref = reference_tables<N>(type);
    const Eigen::Matrix<double, N, 3> X = coords;
    double volume = 0;
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
        double det = 0;
        checked_jacobian<N>(type, ref, X, static_cast<int>(q), det);
        volume += ref.weights[q] * det;
    }
    return volume;
}

}  // namespace

void element_matrices(CellType type, const CellCoords& coords, const Matrix6& C_cylindrical,
                      double density, Eigen::MatrixXd& K, Eigen::MatrixXd& M) {
    switch (type) {
        case CellType::hex20: return integrate_cell<20>(type, coords, C_cylindrical, density, K, M);
        case CellType::hex27: return integrate_cell<27>(type, coords, C_cylindrical, density, K, M);
        case CellType::tet10: return integrate_cell<10>(type, coords, C_cylindrical, density, K, M);
    }
}

Eigen::MatrixXd element_gyroscopic(CellType type, const CellCoords& coords, double density) {
    switch (type) {
        case CellType::hex20: return integrate_gyroscopic<20>(type, coords, density);
        case CellType::hex27: return integrate_gyroscopic<27>(type, coords, density);
        case CellType::tet10: return integrate_gyroscopic<10>(type, coords, density);
    }
    return {};  // unreachable
}

double element_volume(CellType type, const CellCoords& coords) {
    switch (type) {
        case CellType::hex20: return integrate_volume<20>(type, coords);
        case CellType::hex27: return integrate_volume<27>(type, coords);
        case CellType::tet10: return integrate_volume<10>(type, coords);
    }
    return 0;  // unreachable
}

}  // namespace coremodal
