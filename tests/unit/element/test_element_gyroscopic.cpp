// The solid cells' gyroscopic matrix (element_gyroscopic, element/element.hpp):
// skew-symmetric, and on rigid motions about the z axis the closed forms of a
// spinning body's angular momentum. Linear fields are reproduced exactly by
// every isoparametric cell, so these hold on curved and distorted cells alike.
#include "element/element.hpp"
#include "element/shape_functions.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace coremodal;

namespace {

constexpr double kDensity = 7850;
const CellType kTypes[] = {CellType::hex20, CellType::hex27, CellType::tet10};

// The nodal values of a field u(x) on a cell (node-major: 3a + c).
Eigen::VectorXd nodal(const CellCoords& X, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u) {
    Eigen::VectorXd q(3 * X.rows());
    for (Eigen::Index a = 0; a < X.rows(); ++a) q.segment<3>(3 * a) = u(X.row(a).transpose());
    return q;
}

// Spin-axis fields: a twist about z, a radial breathing, tilts about x and y.
Eigen::Vector3d twist(const Eigen::Vector3d& x) { return {-x.y(), x.x(), 0}; }
Eigen::Vector3d breathing(const Eigen::Vector3d& x) { return {x.x(), x.y(), 0}; }
Eigen::Vector3d tilt_x(const Eigen::Vector3d& x) { return {0, -x.z(), x.y()}; }
Eigen::Vector3d tilt_y(const Eigen::Vector3d& x) { return {x.z(), 0, -x.x()}; }

// A cell on a tube sector (r 50-60 mm, theta 0.4-0.9 rad, 30 mm long), its
// nodes on the cylinders, then moved off them to make it curved and uneven.
CellCoords curved_cell(CellType type) {
    const ReferenceCoords& ref = reference_node_coords(type);
    const bool hex = type != CellType::tet10;
    CellCoords X(ref.rows(), 3);
    for (Eigen::Index a = 0; a < ref.rows(); ++a) {
        const Eigen::Vector3d t = hex ? Eigen::Vector3d((ref.row(a).array() + 1.0) / 2.0)
                                      : Eigen::Vector3d(ref.row(a).transpose());
        const double r = 0.05 + 0.01 * t.x() + 0.002 * t.y() * t.z(), theta = 0.4 + 0.5 * t.y();
        X.row(a) << r * std::cos(theta), r * std::sin(theta), 0.03 * t.z() + 0.004 * t.x() * t.y();
    }
    return X;
}

}  // namespace

TEST_CASE("The gyroscopic matrix of a cell is skew-symmetric and not zero", "[element][rotation][gyroscopic]") {
    for (CellType type : kTypes) {
        INFO(cell_type_name(type));
        const Eigen::MatrixXd G = element_gyroscopic(type, curved_cell(type), kDensity);
        REQUIRE(G.rows() == 3 * nodes_per_cell(type));
        CHECK((G + G.transpose()).norm() == 0.0);
        CHECK(G.norm() > 0);
    }
}

TEST_CASE("A box spinning about z: breathing and twist couple by twice its polar moment of inertia",
          "[element][rotation][gyroscopic]") {
    // Box [x0, x1] x [y0, y1] x [z0, z1] off the axis. A spinning body that
    // swells radially (breathing b) slows its spin: with twist angle phi the
    // cross term of the kinetic energy couples them by
    // b^T G phi = -2 int rho r^2 dV = -2 I_z, I_z in closed form; a tilt rx
    // against a tilt ry by ry^T G rx = -I_z, the beam level's rho_J per length
    // (effects/rotation.hpp: G = rho_J [[0, 1], [-1, 0]] on (rx, ry)).
    const double x0 = 0.02, x1 = 0.05, y0 = -0.01, y1 = 0.03, z0 = 0.1, z1 = 0.16;
    const double I_z = kDensity * (z1 - z0) *
                       ((y1 - y0) * (std::pow(x1, 3) - std::pow(x0, 3)) + (x1 - x0) * (std::pow(y1, 3) - std::pow(y0, 3))) / 3;
    const Eigen::Vector3d half((x1 - x0) / 2, (y1 - y0) / 2, (z1 - z0) / 2), centre((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2);
    for (CellType type : {CellType::hex20, CellType::hex27}) {
        INFO(cell_type_name(type));
        const ReferenceCoords& ref = reference_node_coords(type);
        CellCoords X(ref.rows(), 3);
        for (Eigen::Index a = 0; a < ref.rows(); ++a)
            X.row(a) = (half.asDiagonal() * ref.row(a).transpose() + centre).transpose();
        const Eigen::MatrixXd G = element_gyroscopic(type, X, kDensity);
        // 3-point Gauss integrates rho r^2 on a box exactly: round-off only.
        CHECK(nodal(X, breathing).dot(G * nodal(X, twist)) == Approx(-2 * I_z).epsilon(1e-13));
        CHECK(nodal(X, tilt_y).dot(G * nodal(X, tilt_x)) == Approx(-I_z).epsilon(1e-13));
    }
}

TEST_CASE("On a curved cell the same couplings equal the cell's own mass matrix's polar moment",
          "[element][rotation][gyroscopic]") {
    // I_z = b^T M b (b the breathing field: |b|^2 = r^2) by the same
    // quadrature, so the identities above hold to round-off on any cell.
    for (CellType type : kTypes) {
        INFO(cell_type_name(type));
        const CellCoords X = curved_cell(type);
        Eigen::MatrixXd K, M;
        element_matrices(type, X, Matrix6::Identity(), kDensity, K, M);
        const Eigen::MatrixXd G = element_gyroscopic(type, X, kDensity);
        const Eigen::VectorXd b = nodal(X, breathing);
        const double I_z = b.dot(M * b);
        CHECK(b.dot(G * nodal(X, twist)) == Approx(-2 * I_z).epsilon(1e-12));
        CHECK(nodal(X, tilt_y).dot(G * nodal(X, tilt_x)) == Approx(-I_z).epsilon(1e-12));
    }
}
