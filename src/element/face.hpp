// Quadratic quadrilateral faces (8-node serendipity, 9-node Lagrange) in
// gmsh order, for integrals over surfaces: spring layers between core and
// chuck, bearing springs on a shaft end face. Plain Eigen.
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace coremodal {

struct FacePoint {
    Eigen::VectorXd N;     // shape values at the point
    Eigen::Vector3d x;     // position
    double area_weight{};  // quadrature weight x |dx/dxi x dx/deta|
};

// The n-point Gauss-Legendre rule on [-1, 1]: points x, weights w.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w);

// n-point Gauss-Legendre in each direction over the face with the given
// node coordinates (rows, metres). nodes: 8 or 9.
std::vector<FacePoint> face_quadrature(const Eigen::Matrix<double, Eigen::Dynamic, 3>& coords, int n_gauss);

// The same over the part [xi0, xi1] x [eta0, eta1] of the reference square.
std::vector<FacePoint> face_quadrature(const Eigen::Matrix<double, Eigen::Dynamic, 3>& coords, int n_gauss,
                                       double xi0, double xi1, double eta0, double eta1);

// Position of the face point (xi, eta).
Eigen::Vector3d face_point(const Eigen::Matrix<double, Eigen::Dynamic, 3>& coords, double xi, double eta);

// Shape values of an 8- or 9-node face at (xi, eta) in [-1, 1]^2, with derivatives.
void face_shape(int nodes, double xi, double eta, Eigen::VectorXd& N, Eigen::VectorXd& dN_dxi,
                Eigen::VectorXd& dN_deta);

}  // namespace coremodal
