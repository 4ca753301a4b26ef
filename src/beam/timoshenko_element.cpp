#include "beam/timoshenko_element.hpp"

#include "common/error.hpp"

#include <array>
#include <cmath>

namespace coremodal {
namespace {

// Quadratic Lagrange functions on [0, 1], nodes at 0, 1/2, 1, and their
// derivatives with respect to xi.
struct Quadratic {
    Eigen::RowVector3d N, dN;
};

Quadratic quadratic(double xi) {
    Quadratic q;
    q.N << (1 - xi) * (1 - 2 * xi), 4 * xi * (1 - xi), xi * (2 * xi - 1);
    q.dN << 4 * xi - 3, 4 - 8 * xi, 4 * xi - 1;
    return q;
}

// Gauss-Legendre rules on [0, 1].
struct Rule {
    std::array<double, 3> x, w;
    int n;
};
const Rule kFull = {{0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)}, {5.0 / 18, 8.0 / 18, 5.0 / 18}, 3};
const Rule kReduced = {{0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0), 0}, {0.5, 0.5, 0}, 2};

// Where a plane's (w, phi) of node a go among the element's DOFs, and the
// sign that turns them into those DOFs: x-z plane (ux, ry), y-z plane (uy, -rx).
struct PlaneMap {
    int w_dof, phi_dof;
    double phi_sign;
};
constexpr PlaneMap kPlaneXZ = {beam_dof::ux, beam_dof::ry, 1};
constexpr PlaneMap kPlaneYZ = {beam_dof::uy, beam_dof::rx, -1};

void add_plane(BeamElementMatrix& out, const PlaneMatrix& plane, const PlaneMap& map) {
    std::array<int, 6> dof{};
    std::array<double, 6> sign{};
    for (int a = 0; a < kElementNodes; ++a) {
        dof[2 * a] = beam_dof::per_node * a + map.w_dof, sign[2 * a] = 1;
        dof[2 * a + 1] = beam_dof::per_node * a + map.phi_dof, sign[2 * a + 1] = map.phi_sign;
    }
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) out(dof[i], dof[j]) += sign[i] * sign[j] * plane(i, j);
}

// A quadratic bar on one DOF per node (axial uz or torsion rz):
// int stiffness u'^2 and int inertia u^2 over the element.
void add_bar(BeamElementMatrix& K, BeamElementMatrix& M, int dof, double stiffness, double inertia, double L) {
    Eigen::Matrix3d k = Eigen::Matrix3d::Zero(), m = Eigen::Matrix3d::Zero();
    for (int q = 0; q < kFull.n; ++q) {
        const Quadratic s = quadratic(kFull.x[q]);
        k += kFull.w[q] * stiffness / L * s.dN.transpose() * s.dN;
        m += kFull.w[q] * inertia * L * s.N.transpose() * s.N;
    }
    for (int a = 0; a < kElementNodes; ++a)
        for (int b = 0; b < kElementNodes; ++b) {
            K(beam_dof::per_node * a + dof, beam_dof::per_node * b + dof) += k(a, b);
            M(beam_dof::per_node * a + dof, beam_dof::per_node * b + dof) += m(a, b);
        }
}

void check_element(const TimoshenkoElement& e) {
    COREMODAL_ASSERT(e.length > 0);
    COREMODAL_ASSERT(e.section.EI > 0 && e.section.kappa_GA > 0 && e.section.EA > 0 && e.section.GJ > 0);
    COREMODAL_ASSERT(e.section.rho_A > 0 && e.section.rho_I > 0 && e.section.rho_J > 0);
}

}  // namespace

ElementMatrices element_matrices(const TimoshenkoElement& e) {
    check_element(e);
    ElementMatrices out;
    BeamElementMatrix &K = out.K, &M = out.M;
    K.setZero();
    M.setZero();
    const PlaneMatrix k = plane_bending_stiffness(e), m = plane_bending_mass(e);
    for (const PlaneMap& plane : {kPlaneXZ, kPlaneYZ}) {
        add_plane(K, k, plane);
        add_plane(M, m, plane);
    }
    add_bar(K, M, beam_dof::uz, e.section.EA, e.section.rho_A, e.length);
    add_bar(K, M, beam_dof::rz, e.section.GJ, e.section.rho_J, e.length);
    return out;
}

PlaneMatrix plane_bending_stiffness(const TimoshenkoElement& e) {
    const double L = e.length;
    PlaneMatrix k = PlaneMatrix::Zero();
    for (int q = 0; q < kFull.n; ++q) {  // bending: full integration
        const Quadratic s = quadratic(kFull.x[q]);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) k(2 * a + 1, 2 * b + 1) += kFull.w[q] * e.section.EI / L * s.dN(a) * s.dN(b);
    }
    for (int q = 0; q < kReduced.n; ++q) {  // shear gamma = w' - phi: reduced integration against locking
        const Quadratic s = quadratic(kReduced.x[q]);
        Eigen::Matrix<double, 1, 6> B;
        for (int a = 0; a < 3; ++a) B(2 * a) = s.dN(a) / L, B(2 * a + 1) = -s.N(a);
        k += kReduced.w[q] * e.section.kappa_GA * L * B.transpose() * B;
    }
    return k;
}

PlaneMatrix plane_bending_mass(const TimoshenkoElement& e) {
    PlaneMatrix m = PlaneMatrix::Zero();
    for (int q = 0; q < kFull.n; ++q) {
        const Quadratic s = quadratic(kFull.x[q]);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                const double NN = kFull.w[q] * e.length * s.N(a) * s.N(b);
                m(2 * a, 2 * b) += e.section.rho_A * NN;
                m(2 * a + 1, 2 * b + 1) += e.section.rho_I * NN;
            }
    }
    return m;
}

Eigen::RowVector3d element_shape(double xi) { return quadratic(xi).N; }

}  // namespace coremodal
