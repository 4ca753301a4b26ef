#include "effects/web.hpp"

#include <cmath>

namespace coremodal {
namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& p) {
    Eigen::Matrix3d X;
    X << 0, -p.z(), p.y(), p.z(), 0, -p.x(), -p.y(), p.x(), 0;
    return X;
}

}  // namespace

Eigen::Vector3d web_direction(const WebSpec& web) { return {std::cos(web.angle), std::sin(web.angle), 0}; }

Eigen::Vector3d web_tangent_normal(const WebSpec& web) { return {std::sin(web.angle), -std::cos(web.angle), 0}; }

Eigen::Matrix3d web_line_stiffness(const WebSpec& web) {
    const WebSprings k = web_springs(web);
    const Eigen::Vector3d d = web_direction(web), n = web_tangent_normal(web), z(0, 0, 1);
    return k.along * d * d.transpose() + k.across * n * n.transpose() + k.axial * z * z.transpose();
}

Matrix6 web_beam_stiffness_per_length(const WebSpec& web, double radius) {
    Eigen::Matrix<double, 3, 6> A;
    A << Eigen::Matrix3d::Identity(), -cross_matrix(radius * web_tangent_normal(web));
    return A.transpose() * web_line_stiffness(web) * A;
}

}  // namespace coremodal
