#include "element/harmonic_element.hpp"

#include "common/error.hpp"

#include <array>
#include <cmath>

namespace coremodal {
namespace {

constexpr std::array<double, 3> kGaussPoints = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr std::array<double, 3> kGaussWeights = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

// Reference coordinates of the quad8 nodes (gmsh order).
constexpr std::array<std::array<double, 2>, 8> kNodes = {
    {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}}};

// Quadratic 1D Lagrange functions on {-1, 0, 1} for an edge (a, b, m).
Eigen::Vector3d edge_values(double s) { return {s * (s - 1) / 2, s * (s + 1) / 2, 1 - s * s}; }
Eigen::Vector3d edge_derivatives(double s) { return {s - 0.5, s + 0.5, -2 * s}; }

// The cos family's L_n on (U, V, W) (harmonic_quad8_spin_coupling).
Eigen::Matrix3d spin_operator(int n) {
    Eigen::Matrix3d L;
    if (n == 0)
        L << 0, 1, 0, -1, 0, 0, 0, 0, 0;
    else
        L << n, -1, 0, -1, n, 0, 0, 0, n;
    return L;
}

// One Gauss point of a cell: shape values, gradients in (r, z), radius and
// r dr dz times the rule's weight.
struct SectionPoint {
    Eigen::Matrix<double, 8, 1> N;
    Eigen::Matrix<double, 8, 2> dN;
    double r = 0, weight = 0;
};

SectionPoint section_point(const Quad8Coords& x, int i, int j) {
    SectionPoint p;
    p.N = quad8_values(kGaussPoints[i], kGaussPoints[j]);
    const Eigen::Matrix<double, 8, 2> dN_ref = quad8_gradients(kGaussPoints[i], kGaussPoints[j]);
    const Eigen::Matrix2d J = x.transpose() * dN_ref;
    const double det = J.determinant();
    if (!(det > 0)) throw SolveError("section cell with a non-positive Jacobian (" + std::to_string(det) + ")");
    p.dN = dN_ref * J.inverse();
    p.r = p.N.dot(x.col(0));
    p.weight = kGaussWeights[i] * kGaussWeights[j] * det * p.r;
    return p;
}


}  // namespace

double harmonic_weight(int n) { return n == 0 ? 2 * M_PI : M_PI; }

Eigen::Matrix<double, 8, 1> quad8_values(double xi, double eta) {
    Eigen::Matrix<double, 8, 1> N;
    for (int a = 0; a < 8; ++a) {
        const double xa = kNodes[a][0], ea = kNodes[a][1];
        if (a < 4)
            N[a] = 0.25 * (1 + xi * xa) * (1 + eta * ea) * (xi * xa + eta * ea - 1);
        else if (xa == 0)
            N[a] = 0.5 * (1 - xi * xi) * (1 + eta * ea);
        else
            N[a] = 0.5 * (1 + xi * xa) * (1 - eta * eta);
    }
    return N;
}

Eigen::Matrix<double, 8, 2> quad8_gradients(double xi, double eta) {
    Eigen::Matrix<double, 8, 2> dN;
    for (int a = 0; a < 8; ++a) {
        const double xa = kNodes[a][0], ea = kNodes[a][1];
        if (a < 4) {
            dN(a, 0) = 0.25 * xa * (1 + eta * ea) * (2 * xi * xa + eta * ea);
            dN(a, 1) = 0.25 * ea * (1 + xi * xa) * (xi * xa + 2 * eta * ea);
        } else if (xa == 0) {
            dN(a, 0) = -xi * (1 + eta * ea);
            dN(a, 1) = 0.5 * (1 - xi * xi) * ea;
        } else {
            dN(a, 0) = 0.5 * xa * (1 - eta * eta);
            dN(a, 1) = -eta * (1 + xi * xa);
        }
    }
    return dN;
}

HarmonicMatrices harmonic_quad8_matrices(const Quad8Coords& x, const Matrix6& C, double density, int n) {
    for (int a = 0; a < 8; ++a)
        if (x(a, 0) < 0) throw SolveError("section node at r = " + std::to_string(x(a, 0)) + " m < 0");
    const double w_n = harmonic_weight(n);
    HarmonicMatrices out;
    out.K.setZero();
    out.M.setZero();
    Eigen::Matrix<double, 6, 24> B;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double xi = kGaussPoints[i], eta = kGaussPoints[j];
            const Eigen::Matrix<double, 8, 1> N = quad8_values(xi, eta);
            const Eigen::Matrix<double, 8, 2> dN_ref = quad8_gradients(xi, eta);
            const Eigen::Matrix2d J = x.transpose() * dN_ref;  // J(i, j) = d x_i / d xi_j
            const double det = J.determinant();
            if (!(det > 0)) throw SolveError("section cell with a non-positive Jacobian (" + std::to_string(det) + ")");
            const Eigen::Matrix<double, 8, 2> dN = dN_ref * J.inverse();  // d N / d (r, z)
            const double r = N.dot(x.col(0));
            const double dV = kGaussWeights[i] * kGaussWeights[j] * det * r;
            B.setZero();
            for (int a = 0; a < 8; ++a) {
                const int u = 3 * a, v = u + 1, w = u + 2;
                const double Nr = dN(a, 0), Nz = dN(a, 1), N_r = N[a] / r;
                B(0, u) = Nr;
                B(1, u) = N_r;
                B(1, v) = -n * N_r;
                B(2, w) = Nz;
                B(3, v) = Nz;
                B(3, w) = n * N_r;
                B(4, u) = Nz;
                B(4, w) = Nr;
                B(5, u) = n * N_r;
                B(5, v) = Nr - N_r;
            }
            out.K.noalias() += (w_n * dV) * B.transpose() * C * B;
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b) {
                    const double m = w_n * density * N[a] * N[b] * dV;
                    for (int c = 0; c < 3; ++c) out.M(3 * a + c, 3 * b + c) += m;
                }
            out.mass += 2 * M_PI * density * dV;
        }
    return out;
}

Quad8Matrix harmonic_quad8_spin_coupling(const Quad8Coords& x, double density, int n) {
    const Eigen::Matrix3d L = spin_operator(n);
    const double w_n = harmonic_weight(n);
    Quad8Matrix out = Quad8Matrix::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Eigen::Matrix<double, 8, 1> N = quad8_values(kGaussPoints[i], kGaussPoints[j]);
            const Eigen::Matrix2d J = x.transpose() * quad8_gradients(kGaussPoints[i], kGaussPoints[j]);
            const double r = N.dot(x.col(0));
            const double weight = w_n * density * kGaussWeights[i] * kGaussWeights[j] * J.determinant() * r;
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b) out.block<3, 3>(3 * a, 3 * b) += (weight * N[a] * N[b]) * L;
        }
    return out;
}

Eigen::Matrix<double, 24, 1> harmonic_quad8_centrifugal_load(const Quad8Coords& x, double density) {
    Eigen::Matrix<double, 24, 1> f = Eigen::Matrix<double, 24, 1>::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const SectionPoint p = section_point(x, i, j);
            for (int a = 0; a < 8; ++a) f[3 * a] += harmonic_weight(0) * density * p.N[a] * p.r * p.weight;
        }
    return f;
}

SectionStress harmonic_quad8_stress(const Quad8Coords& x, const Matrix6& C, const Eigen::Matrix<double, 24, 1>& u) {
    SectionStress out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const SectionPoint p = section_point(x, i, j);
            // The n = 0 strains (rr, tt, zz, tz, rz, rt) of the header's B.
            Eigen::Matrix<double, 6, 1> eps = Eigen::Matrix<double, 6, 1>::Zero();
            for (int a = 0; a < 8; ++a) {
                const double U = u[3 * a], V = u[3 * a + 1], W = u[3 * a + 2];
                const double Nr = p.dN(a, 0), Nz = p.dN(a, 1), N_r = p.N[a] / p.r;
                eps[0] += Nr * U;
                eps[1] += N_r * U;
                eps[2] += Nz * W;
                eps[3] += Nz * V;
                eps[4] += Nz * U + Nr * W;
                eps[5] += (Nr - N_r) * V;
            }
            const Eigen::Matrix<double, 6, 1> sigma = C * eps;
            out.col(3 * i + j) << sigma[0], sigma[1], sigma[2], sigma[4];
        }
    return out;
}

Quad8Matrix harmonic_quad8_centrifugal(const Quad8Coords& x, double density, const SectionStress& sigma, int n) {
    const Eigen::Matrix3d L = spin_operator(n);
    const Eigen::Matrix3d LtL = L.transpose() * L;
    const double w_n = harmonic_weight(n);
    Quad8Matrix out = Quad8Matrix::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const SectionPoint p = section_point(x, i, j);
            const Eigen::Vector4d s = sigma.col(3 * i + j);  // rr, tt, zz, rz
            Eigen::Matrix2d S;
            S << s[0], s[3], s[3], s[2];
            const double around = s[1] / (p.r * p.r) - density;
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b) {
                    const double in_section = p.dN.row(a) * S * p.dN.row(b).transpose();
                    out.block<3, 3>(3 * a, 3 * b) += (w_n * p.weight) * (in_section * Eigen::Matrix3d::Identity() +
                                                                        around * p.N[a] * p.N[b] * LtL);
                }
        }
    return out;
}

Eigen::Matrix<double, 9, 9> harmonic_edge_spring(const Eigen::Matrix<double, 3, 2>& x, const Eigen::Vector3d& k, int n) {
    Eigen::Matrix<double, 9, 9> K = Eigen::Matrix<double, 9, 9>::Zero();
    const double w_n = harmonic_weight(n);
    for (int g = 0; g < 3; ++g) {
        const double s = kGaussPoints[g];
        const Eigen::Vector3d N = edge_values(s);
        const Eigen::Vector2d dx = x.transpose() * edge_derivatives(s);
        const double r = N.dot(x.col(0));
        const double w = w_n * kGaussWeights[g] * dx.norm() * r;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                for (int c = 0; c < 3; ++c) K(3 * a + c, 3 * b + c) += w * N[a] * N[b] * k[c];
    }
    return K;
}

}  // namespace coremodal
