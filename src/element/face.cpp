#include "element/face.hpp"

#include "element/shape_functions.hpp"

#include <stdexcept>

namespace coremodal {
namespace {

// gmsh's reference positions: corners, then mid-edges, then the centre.
constexpr double kNodeXi[9] = {-1, 1, 1, -1, 0, 1, 0, -1, 0};
constexpr double kNodeEta[9] = {-1, -1, 1, 1, -1, 0, 1, 0, 0};

}  // namespace

void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
    x.resize(n);
    w.resize(n);
    for (int i = 0; i < n; ++i) {  // Newton on P_n from Chebyshev guesses
        double t = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = t;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (t * p1 - p0) / (t * t - 1);
            const double step = p1 / dp;
            t -= step;
            if (std::abs(step) < 1e-15) break;
        }
        x[i] = t;
        w[i] = 2 / ((1 - t * t) * dp * dp);
    }
}

void face_shape(int nodes, double xi, double eta, Eigen::VectorXd& N, Eigen::VectorXd& dN_dxi,
                Eigen::VectorXd& dN_deta) {
    N.resize(nodes);
    dN_dxi.resize(nodes);
    dN_deta.resize(nodes);
    if (nodes == 9) {
        for (int a = 0; a < 9; ++a) {
            double lx, dlx, ly, dly;
            lagrange_1d(xi, kNodeXi[a], lx, dlx);
            lagrange_1d(eta, kNodeEta[a], ly, dly);
            N[a] = lx * ly;
            dN_dxi[a] = dlx * ly;
            dN_deta[a] = lx * dly;
        }
        return;
    }
    if (nodes != 8) throw std::invalid_argument("face_shape: faces have 8 or 9 nodes");
    for (int a = 0; a < 4; ++a) {  // serendipity corners
        const double s = kNodeXi[a], t = kNodeEta[a];
        N[a] = 0.25 * (1 + s * xi) * (1 + t * eta) * (s * xi + t * eta - 1);
        dN_dxi[a] = 0.25 * s * (1 + t * eta) * (2 * s * xi + t * eta);
        dN_deta[a] = 0.25 * t * (1 + s * xi) * (s * xi + 2 * t * eta);
    }
    for (int a = 4; a < 8; ++a) {
        const double s = kNodeXi[a], t = kNodeEta[a];
        if (s == 0) {
            N[a] = 0.5 * (1 - xi * xi) * (1 + t * eta);
            dN_dxi[a] = -xi * (1 + t * eta);
            dN_deta[a] = 0.5 * t * (1 - xi * xi);
        } else {
            N[a] = 0.5 * (1 + s * xi) * (1 - eta * eta);
            dN_dxi[a] = 0.5 * s * (1 - eta * eta);
            dN_deta[a] = -eta * (1 + s * xi);
        }
    }
}

std::vector<FacePoint> face_quadrature(const Eigen::Matrix<double, Eigen::Dynamic, 3>& coords, int n_gauss) {
    return face_quadrature(coords, n_gauss, -1, 1, -1, 1);
}

std::vector<FacePoint> face_quadrature(const Eigen::Matrix<double, Eigen::Dynamic, 3>& coords, int n_gauss,
                                       double xi0, double xi1, double eta0, double eta1) {
    std::vector<double> g, w;
    gauss_legendre(n_gauss, g, w);
    const int nodes = static_cast<int>(coords.rows());
    const double hx = (xi1 - xi0) / 2, hy = (eta1 - eta0) / 2;
    std::vector<FacePoint> points;
    Eigen::VectorXd N, dxi, deta;
    for (int i = 0; i < n_gauss; ++i)
        for (int j = 0; j < n_gauss; ++j) {
            face_shape(nodes, xi0 + hx * (g[i] + 1), eta0 + hy * (g[j] + 1), N, dxi, deta);
            const Eigen::Vector3d tx = coords.transpose() * dxi, ty = coords.transpose() * deta;
            points.push_back({N, coords.transpose() * N, hx * hy * w[i] * w[j] * tx.cross(ty).norm()});
        }
    return points;
}

Eigen::Vector3d face_point(const Eigen::Matrix<double, Eigen::Dynamic, 3>& coords, double xi, double eta) {
    Eigen::VectorXd N, dxi, deta;
    face_shape(static_cast<int>(coords.rows()), xi, eta, N, dxi, deta);
    return coords.transpose() * N;
}

}  // namespace coremodal
