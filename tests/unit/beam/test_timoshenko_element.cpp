// The three-node Timoshenko element (src/beam/timoshenko_element.hpp): rigid
// motions cost no energy, the mass matrix carries the section's mass and
// inertia exactly, and the two bending planes are the same plane element.
#include "beam/timoshenko_element.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

// Arbitrary but distinct section values, so that a mixed-up term shows.
TimoshenkoElement test_element() {
    BeamSection s;
    s.EI = 3.0e5, s.kappa_GA = 1.2e7, s.EA = 5.0e8, s.GJ = 4.0e5;
    s.rho_A = 15.0, s.rho_I = 0.02, s.rho_J = 0.04;
    return {0.3, s};
}

// A rigid motion of the three nodes (at z = 0, L/2, L): translation t and
// small rotation r about the origin, u = t + r x (0, 0, z).
Eigen::Matrix<double, kElementDofs, 1> rigid_motion(const Eigen::Vector3d& t, const Eigen::Vector3d& r, double L) {
    Eigen::Matrix<double, kElementDofs, 1> q;
    for (int a = 0; a < kElementNodes; ++a) {
        const Eigen::Vector3d u = t + r.cross(Eigen::Vector3d(0, 0, 0.5 * a * L));
        q.segment<3>(6 * a) = u;
        q.segment<3>(6 * a + 3) = r;
    }
    return q;
}

}  // namespace

TEST_CASE("Rigid motions of an element cost no strain energy", "[beam][element]") {
    const TimoshenkoElement e = test_element();
    const BeamElementMatrix K = element_matrices(e).K;
    CHECK((K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-15 * K.cwiseAbs().maxCoeff());
    for (int i = 0; i < 3; ++i) {
        // Relative to the largest stiffness entry: rounding only.
        const Eigen::Vector3d unit = Eigen::Vector3d::Unit(i);
        CHECK((K * rigid_motion(unit, Eigen::Vector3d::Zero(), e.length)).norm() < 1e-12 * K.norm());
        CHECK((K * rigid_motion(Eigen::Vector3d::Zero(), unit, e.length)).norm() < 1e-12 * K.norm());
    }
}

TEST_CASE("The element mass matrix carries the section's mass and inertia exactly", "[beam][element]") {
    const TimoshenkoElement e = test_element();
    const BeamElementMatrix M = element_matrices(e).M;
    const double L = e.length;
    for (int i = 0; i < 3; ++i) {
        const auto t = rigid_motion(Eigen::Vector3d::Unit(i), Eigen::Vector3d::Zero(), L);
        CHECK(t.dot(M * t) == Approx(e.section.rho_A * L).epsilon(1e-14));  // translation: rho A L
    }
    // Rotation about z: the polar inertia rho J L.
    const auto rz = rigid_motion(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), L);
    CHECK(rz.dot(M * rz) == Approx(e.section.rho_J * L).epsilon(1e-14));
    // Rotation about x through z = 0: rho A (L^3 / 3) from the translations
    // uy = -z theta, plus the rotary inertia rho I L (quadratic shapes
    // integrate z^2 exactly).
    const auto rx = rigid_motion(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), L);
    CHECK(rx.dot(M * rx) == Approx(e.section.rho_A * L * L * L / 3 + e.section.rho_I * L).epsilon(1e-13));
}

TEST_CASE("Both bending planes use the same plane element, with rx = -d uy/dz", "[beam][element]") {
    const TimoshenkoElement e = test_element();
    const ElementMatrices m = element_matrices(e);
    // A bending shape of the x-z plane and its image in the y-z plane.
    Eigen::Matrix<double, kElementDofs, 1> xz = Eigen::Matrix<double, kElementDofs, 1>::Zero(), yz = xz;
    const double w[3] = {0.0, 1.0, 0.3}, phi[3] = {0.7, -0.2, 0.5};
    for (int a = 0; a < 3; ++a) {
        xz(6 * a + beam_dof::ux) = w[a], xz(6 * a + beam_dof::ry) = phi[a];
        yz(6 * a + beam_dof::uy) = w[a], yz(6 * a + beam_dof::rx) = -phi[a];
    }
    CHECK(yz.dot(m.K * yz) == Approx(xz.dot(m.K * xz)).epsilon(1e-14));
    CHECK(yz.dot(m.M * yz) == Approx(xz.dot(m.M * xz)).epsilon(1e-14));
    CHECK(std::abs(xz.dot(m.K * yz)) < 1e-12 * xz.dot(m.K * xz));  // the planes do not couple
}

TEST_CASE("One element bends a cantilever exactly, slender or thick: no shear locking", "[beam][element]") {
    // Tip load P on a cantilever: w(L) = P L^3 / (3 EI) + P L / (kappa G A).
    // The rotation phi of the exact solution is quadratic, and 2-point
    // reduced integration asks w' = phi only where Gauss integrates phi
    // exactly, so one quadratic element gets both terms exactly, at
    // EI / (kappa G A L^2) = 1e-6 (where full integration would lock) as at 1.
    for (double ratio : {1e-6, 1.0}) {
        TimoshenkoElement e = test_element();
        e.section.kappa_GA = e.section.EI / (ratio * e.length * e.length);
        const PlaneMatrix K = plane_bending_stiffness(e);
        const Eigen::Matrix4d free = K.bottomRightCorner<4, 4>();  // node 1 (w, phi) clamped
        const Eigen::Vector4d u = free.ldlt().solve(Eigen::Vector4d(0, 0, 1, 0));
        const double exact = std::pow(e.length, 3) / (3 * e.section.EI) + e.length / e.section.kappa_GA;
        INFO("EI / (kappa G A L^2) = " << ratio);
        CHECK(u(2) == Approx(exact).epsilon(1e-8));  // the slender system is conditioned ~1/ratio
    }
}
