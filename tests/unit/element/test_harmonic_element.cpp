// The axisymmetric-harmonic quad8: shape functions, rigid-body motions that
// must cost no energy in their harmonic, the revolved mass, and the ring
// spring's area.
#include "element/harmonic_element.hpp"

#include "support/test_materials.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

// A curved-edged cell of a thick ring: r in [ri, ro], z in [z0, z1], one mid-edge node pushed off.
Quad8Coords ring_cell(double ri = 0.038, double ro = 0.053, double z0 = 0.1, double z1 = 0.13) {
    Quad8Coords x;
    x << ri, z0, ro, z0, ro, z1, ri, z1, (ri + ro) / 2, z0, ro, (z0 + z1) / 2, (ri + ro) / 2, z1, ri, (z0 + z1) / 2;
    x(5, 0) += 0.002;  // a curved outer edge: the motions below are still exact
    return x;
}

// Node values of a field given as (U, V, W) functions of (r, z).
template <class F>
Eigen::Matrix<double, 24, 1> field(const Quad8Coords& x, F f) {
    Eigen::Matrix<double, 24, 1> u;
    for (int a = 0; a < 8; ++a) u.segment<3>(3 * a) = f(x(a, 0), x(a, 1));
    return u;
}

double energy(const Quad8Matrix& K, const Eigen::Matrix<double, 24, 1>& u) { return u.dot(K * u); }

}  // namespace

TEST_CASE("quad8 shape functions: partition of unity, Kronecker delta, gradients sum to zero", "[harmonic]") {
    const Quad8Coords x = ring_cell();
    for (double xi : {-1.0, -0.3, 0.5})
        for (double eta : {-0.7, 0.2, 1.0}) {
            CHECK(quad8_values(xi, eta).sum() == Approx(1.0).margin(1e-14));
            CHECK(quad8_gradients(xi, eta).colwise().sum().norm() == Approx(0).margin(1e-14));
        }
    const double nodes[8][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    for (int a = 0; a < 8; ++a) {
        const auto N = quad8_values(nodes[a][0], nodes[a][1]);
        for (int b = 0; b < 8; ++b) CHECK(N[b] == Approx(a == b ? 1.0 : 0.0).margin(1e-14));
    }
}

TEST_CASE("harmonic quad8: rigid motions cost no energy in their harmonic, others do", "[harmonic]") {
    const Quad8Coords x = ring_cell();
    const Matrix6 C = stiffness_cylindrical(coremodal::testing::paperboard());
    const auto K0 = harmonic_quad8_matrices(x, C, 700, 0).K;
    const auto K1 = harmonic_quad8_matrices(x, C, 700, 1).K;
    const auto K2 = harmonic_quad8_matrices(x, C, 700, 2).K;
    const double scale = K1.norm() * 10;  // fields of size ~1 on 8 nodes: roundoff ~ 1e-16 |K| |u|^2
    // n = 0: axial translation and rotation about the axis (u_theta = -V = -r).
    CHECK(energy(K0, field(x, [](double, double) { return Eigen::Vector3d(0, 0, 1); })) == Approx(0).margin(1e-13 * scale));
    CHECK(energy(K0, field(x, [](double r, double) { return Eigen::Vector3d(0, r, 0); })) == Approx(0).margin(1e-13 * scale));
    // n = 1: sideways translation (U = V = 1) and tilt about y (u_x = z, u_z = -x: U = V = z, W = -r).
    CHECK(energy(K1, field(x, [](double, double) { return Eigen::Vector3d(1, 1, 0); })) == Approx(0).margin(1e-13 * scale));
    CHECK(energy(K1, field(x, [](double r, double z) { return Eigen::Vector3d(z, z, -r); })) == Approx(0).margin(1e-13 * scale));
    // The same fields strain the ring in other harmonics; uniform radial growth strains it in all.
    CHECK(energy(K2, field(x, [](double, double) { return Eigen::Vector3d(1, 1, 0); })) > 1e-8 * scale);
    CHECK(energy(K0, field(x, [](double, double) { return Eigen::Vector3d(1, 0, 0); })) > 1e-8 * scale);
    // Symmetric, positive semi-definite.
    CHECK((K2 - K2.transpose()).norm() <= 1e-12 * K2.norm());
    CHECK(Eigen::SelfAdjointEigenSolver<Quad8Matrix>(K2).eigenvalues().minCoeff() > -1e-10 * K2.norm());
}

TEST_CASE("harmonic quad8: the mass is rho times the revolved volume; M carries the theta weight", "[harmonic]") {
    const double ri = 0.038, ro = 0.053, z0 = 0.1, z1 = 0.13, rho = 700;
    Quad8Coords x = ring_cell(ri, ro, z0, z1);
    x(5, 0) -= 0.002;  // straight edges: an exact annulus
    const double volume = M_PI * (ro * ro - ri * ri) * (z1 - z0);
    for (int n : {0, 1, 3}) {
        const auto e = harmonic_quad8_matrices(x, Matrix6::Identity(), rho, n);
        CHECK(e.mass == Approx(rho * volume).epsilon(1e-12));
        // W = 1 everywhere: the kinetic energy of cos n theta (n > 0) is half that of a uniform field.
        const auto w = field(x, [](double, double) { return Eigen::Vector3d(0, 0, 1); });
        CHECK(w.dot(e.M * w) == Approx(rho * volume * (n == 0 ? 1.0 : 0.5)).epsilon(1e-12));
    }
}

TEST_CASE("harmonic edge spring: unit stiffness integrates the revolved area", "[harmonic]") {
    Eigen::Matrix<double, 3, 2> bore;  // along z at r = 0.038, 0.1 to 0.18
    bore << 0.038, 0.1, 0.038, 0.18, 0.038, 0.14;
    const auto K = harmonic_edge_spring(bore, {1, 2, 3}, 0);
    Eigen::Matrix<double, 9, 1> w = Eigen::Matrix<double, 9, 1>::Zero();
    for (int p = 0; p < 3; ++p) w[3 * p + 2] = 1;
    CHECK(w.dot(K * w) == Approx(3 * 2 * M_PI * 0.038 * 0.08).epsilon(1e-12));
    Eigen::Matrix<double, 3, 2> face;  // along r at z = 0, 0 to 0.05: a disc
    face << 0, 0, 0.05, 0, 0.025, 0;
    const auto Kd = harmonic_edge_spring(face, {1, 1, 1}, 1);
    Eigen::Matrix<double, 9, 1> u = Eigen::Matrix<double, 9, 1>::Zero();
    for (int p = 0; p < 3; ++p) u[3 * p] = 1;
    CHECK(u.dot(Kd * u) == Approx(M_PI * 0.05 * 0.05 / 2).epsilon(1e-12));  // cos^2 over the disc
}

TEST_CASE("harmonic quad8 spin coupling: symmetric for n >= 1, skew for n = 0; a tilt carries rho I, a translation "
          "nothing", "[harmonic][rotation]") {
    const Quad8Coords x = ring_cell();
    const double rho = 700;
    const Quad8Matrix g1 = harmonic_quad8_spin_coupling(x, rho, 1);
    const Quad8Matrix g0 = harmonic_quad8_spin_coupling(x, rho, 0);
    // Round-off only: the products of the same numbers summed in another order.
    CHECK((g1 - g1.transpose()).cwiseAbs().maxCoeff() <= 1e-15 * g1.cwiseAbs().maxCoeff());
    CHECK((g0 + g0.transpose()).cwiseAbs().maxCoeff() <= 1e-15 * g0.cwiseAbs().maxCoeff());
    // A sideways translation (n = 1: U = V = 1) is not moved by the spin: L u = 0.
    const auto translation = field(x, [](double, double) { return Eigen::Vector3d(1, 1, 0); });
    CHECK((g1 * translation).cwiseAbs().maxCoeff() < 1e-12 * g1.cwiseAbs().maxCoeff());
    // A tilt about y (u_x = z, u_z = -x: U = V = z, W = -r) has
    // a^T Gamma a = pi int rho r^2 r dr dz = rho I_y over the cell's length:
    // the beam's rho_I, half its rho_J (G = 2 Gamma: effects/rotation.hpp).
    // On a straight-edged cell r^3 det J is cubic: the 3 x 3 rule is exact.
    Quad8Coords straight = x;
    straight(5, 0) -= 0.002;
    const double ri = 0.038, ro = 0.053, length = 0.03;
    const auto tilt = field(straight, [](double r, double z) { return Eigen::Vector3d(z, z, -r); });
    const Quad8Matrix g = harmonic_quad8_spin_coupling(straight, rho, 1);
    CHECK(tilt.dot(g * tilt) == Approx(M_PI * rho * (std::pow(ro, 4) - std::pow(ri, 4)) / 4 * length).epsilon(1e-12));
}
