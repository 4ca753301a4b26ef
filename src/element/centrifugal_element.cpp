// The centrifugal term's element kernels (centrifugal_element.hpp). They run
// once per cell and spinning scene (not per speed), so plain dynamic Eigen
// is fast enough; element.cpp's hand-vectorised loop is for the stiffness,
// which every run assembles.
#include "element/centrifugal_element.hpp"

#include "element/quadrature.hpp"
#include "element/shape_functions.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coremodal {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

// One integration point of a cell: shape values, physical gradients
// (n x 3), position and weight times Jacobian.
struct PointGeometry {
    Eigen::VectorXd N;
    Eigen::MatrixXd G;
    Eigen::Vector3d x;
    double w_det = 0;
    // d/dtheta = x d/dy - y d/dx of every shape function (the material's
    // convective derivative per unit spin, effects/rotation.hpp).
    Eigen::VectorXd d_theta() const { return x.x() * G.col(1) - x.y() * G.col(0); }
};

std::vector<PointGeometry> point_geometry(CellType type, const CellCoords& coords) {
    const QuadratureRule& rule = full_integration_rule(type);
    std::vector<PointGeometry> points;
    for (int q = 0; q < rule.size(); ++q) {
        PointGeometry p;
        p.N = shape_values(type, rule.points[q]);
        const Eigen::MatrixXd dN = shape_gradients(type, rule.points[q]);
        const Eigen::Matrix3d J = coords.transpose() * dN;
        const double det = J.determinant();
        if (!(det > 0)) {
            std::ostringstream msg;
            msg << cell_type_name(type) << " cell: Jacobian determinant " << det << " <= 0 at integration point "
                << q + 1 << " of " << rule.size() << "; the cell is inverted or badly distorted";
            throw std::runtime_error(msg.str());
        }
        p.G = dN * J.inverse();
        p.x = coords.transpose() * p.N;
        p.w_det = rule.weights[q] * det;
        points.push_back(std::move(p));
    }
    return points;
}

// s (x) I3 in node-major DOF order.
Eigen::MatrixXd expand_by_identity(const Eigen::MatrixXd& s) {
    const Eigen::Index n = s.rows();
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (Eigen::Index b = 0; b < n; ++b)
        for (Eigen::Index a = 0; a < n; ++a)
            for (int c = 0; c < 3; ++c) out(3 * a + c, 3 * b + c) = s(a, b);
    return out;
}

// Engineering strain (xx, yy, zz, yz, xz, xy) of the nodal displacements u at a point.
Vector6 strain(const Eigen::MatrixXd& G, const Eigen::VectorXd& u) {
    // grad u (i, j) = du_i / dx_j = sum_a u_a,i G(a, j)
    const Eigen::Index n = G.rows();
    const Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>> U(u.data(), 3, n);
    const Eigen::Matrix3d H = U * G;
    Vector6 e;
    e << H(0, 0), H(1, 1), H(2, 2), H(1, 2) + H(2, 1), H(0, 2) + H(2, 0), H(0, 1) + H(1, 0);
    return e;
}

Eigen::Matrix3d tensor(const Vector6& s) {
    Eigen::Matrix3d t;
    t << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
    return t;
}

}  // namespace

Eigen::VectorXd element_centrifugal_load(CellType type, const CellCoords& coords, double density) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * coords.rows());
    for (const PointGeometry& p : point_geometry(type, coords))
        for (Eigen::Index a = 0; a < p.N.size(); ++a) {
            const double s = density * p.w_det * p.N[a];
            f[3 * a] += s * p.x.x();
            f[3 * a + 1] += s * p.x.y();
        }
    return f;
}

std::vector<PointStress> element_stresses(CellType type, const CellCoords& coords, const Matrix6& C_cylindrical,
                                          const Eigen::VectorXd& u) {
    std::vector<PointStress> out;
    for (const PointGeometry& p : point_geometry(type, coords)) {
        // As element_matrices: the cylindrical stiffness turned to the
        // point's polar angle (atan2(0, 0) = 0 on the axis, isotropic there).
        const Matrix6 C = rotate_to_global(C_cylindrical, std::atan2(p.x.y(), p.x.x()));
        out.push_back({p.x, tensor(C * strain(p.G, u))});
    }
    return out;
}

Eigen::MatrixXd element_stress_stiffness(CellType type, const CellCoords& coords,
                                         const std::vector<PointStress>& stresses) {
    const std::vector<PointGeometry> points = point_geometry(type, coords);
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(coords.rows(), coords.rows());
    for (size_t q = 0; q < points.size(); ++q)
        s.noalias() += points[q].w_det * points[q].G * stresses.at(q).sigma * points[q].G.transpose();
    return expand_by_identity(s);
}

Eigen::MatrixXd element_spin_softening(CellType type, const CellCoords& coords, double density) {
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(coords.rows(), coords.rows());
    for (const PointGeometry& p : point_geometry(type, coords)) {
        const Eigen::VectorXd d = p.d_theta();
        s.noalias() += density * p.w_det * d * d.transpose();
    }
    return expand_by_identity(s);
}

Eigen::MatrixXd element_centrifugal(CellType type, const CellCoords& coords, const Matrix6& C_cylindrical,
                                    double density, const Eigen::VectorXd& u1) {
    return element_stress_stiffness(type, coords, element_stresses(type, coords, C_cylindrical, u1)) -
           element_spin_softening(type, coords, density);
}

}  // namespace coremodal
