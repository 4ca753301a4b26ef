// The centrifugal term's element kernels (element/centrifugal_element.hpp)
// against what isoparametric cells reproduce exactly: linear fields. On a
// curved, uneven cell the load is the mass matrix times the nodal (x, y, 0),
// a homogeneous strain gives the stress C eps at every point, a rigid
// translation has no K_Omega, and the spin softening of a twist or a radial
// breathing is the cell's polar moment of inertia int rho r^2 dV.
#include "element/centrifugal_element.hpp"
#include "element/shape_functions.hpp"
#include "material/material.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace coremodal;

namespace {

constexpr double kDensity = 7850;
const CellType kTypes[] = {CellType::hex20, CellType::hex27, CellType::tet10};

Eigen::VectorXd nodal(const CellCoords& X, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u) {
    Eigen::VectorXd q(3 * X.rows());
    for (Eigen::Index a = 0; a < X.rows(); ++a) q.segment<3>(3 * a) = u(X.row(a).transpose());
    return q;
}

// A cell on a tube sector (r 50-60 mm, theta 0.4-0.9 rad, 30 mm long),
// moved off the cylinders to make it curved and uneven (as the gyroscopic test's).
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

Matrix6 steel() { return stiffness_cylindrical(OrthotropicMaterial::isotropic("steel", 210e9, 0.3, kDensity)); }

// Some displacement that is not a rigid motion (a static state to build K_sigma1 on).
Eigen::Vector3d wavy(const Eigen::Vector3d& x) {
    return {1e-4 * x.x() + 3e-3 * x.y() * x.z(), 2e-4 * x.y() * x.y(), -5e-5 * x.z() + 1e-3 * x.x() * x.y()};
}

}  // namespace

TEST_CASE("The centrifugal load of a cell is its mass matrix times the nodal (x, y, 0)", "[element][rotation][centrifugal]") {
    for (CellType type : kTypes) {
        INFO(cell_type_name(type));
        const CellCoords X = curved_cell(type);
        Eigen::MatrixXd K, M;
        element_matrices(type, X, steel(), kDensity, K, M);
        const Eigen::VectorXd expected = M * nodal(X, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(x.x(), x.y(), 0); });
        const Eigen::VectorXd f = element_centrifugal_load(type, X, kDensity);
        CHECK((f - expected).norm() <= 1e-13 * expected.norm());
    }
}

TEST_CASE("A homogeneous strain gives the stress C eps at every integration point", "[element][rotation][centrifugal]") {
    // Isotropic: the point's polar angle does not change C.
    Eigen::Matrix<double, 6, 1> eps;
    eps << 1e-4, -2e-4, 3e-4, 4e-4, -1e-4, 2e-4;  // engineering shears
    const Eigen::Matrix<double, 6, 1> s = steel() * eps;
    Eigen::Matrix3d expected;
    expected << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
    const auto strain_field = [&](const Eigen::Vector3d& x) {
        Eigen::Matrix3d e;  // tensor strain
        e << eps[0], eps[5] / 2, eps[4] / 2, eps[5] / 2, eps[1], eps[3] / 2, eps[4] / 2, eps[3] / 2, eps[2];
        return Eigen::Vector3d(e * x);
    };
    for (CellType type : kTypes) {
        INFO(cell_type_name(type));
        const CellCoords X = curved_cell(type);
        for (const PointStress& p : element_stresses(type, X, steel(), nodal(X, strain_field)))
            CHECK((p.sigma - expected).norm() <= 1e-10 * expected.norm());
    }
}

TEST_CASE("K_Omega of a cell does nothing to a rigid translation", "[element][rotation][centrifugal]") {
    // grad of a constant field is zero and so is its d/dtheta: K_sigma1 and
    // M_L both vanish on it, to round-off (effects/rotation.hpp: a Jeffcott
    // rotor's whirl has no Omega^2 term in the stationary frame).
    for (CellType type : kTypes) {
        INFO(cell_type_name(type));
        const CellCoords X = curved_cell(type);
        const Eigen::MatrixXd k = element_centrifugal(type, X, steel(), kDensity, nodal(X, wavy));
        CHECK((k - k.transpose()).norm() <= 1e-14 * k.norm());
        for (int c = 0; c < 3; ++c) {
            const Eigen::VectorXd t = nodal(X, [c](const Eigen::Vector3d&) { return Eigen::Vector3d::Unit(c); });
            CHECK((k * t).norm() <= 1e-13 * k.norm() * t.norm());
        }
    }
}

TEST_CASE("The spin softening of a twist and of a radial breathing is the cell's polar moment of inertia",
          "[element][rotation][centrifugal]") {
    // d/dtheta of the twist (-y, x, 0) is (-x, -y, 0), of the breathing
    // (x, y, 0) is (-y, x, 0): both |.|^2 = r^2, so q^T M_L q = int rho r^2 dV
    // = b^T M b with the cell's own mass matrix (b the breathing).
    for (CellType type : kTypes) {
        INFO(cell_type_name(type));
        const CellCoords X = curved_cell(type);
        Eigen::MatrixXd K, M;
        element_matrices(type, X, steel(), kDensity, K, M);
        const Eigen::VectorXd b = nodal(X, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(x.x(), x.y(), 0); });
        const Eigen::VectorXd w = nodal(X, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(-x.y(), x.x(), 0); });
        const double I_z = b.dot(M * b);
        const Eigen::MatrixXd M_L = element_spin_softening(type, X, kDensity);
        CHECK(b.dot(M_L * b) == Approx(I_z).epsilon(1e-12));
        CHECK(w.dot(M_L * w) == Approx(I_z).epsilon(1e-12));
    }
}
