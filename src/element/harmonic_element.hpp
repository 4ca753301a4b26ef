// The axisymmetric-harmonic element: an 8-node serendipity quadrilateral of
// the r–z section carrying one circumferential wave number n.
//
// A cylindrically orthotropic body of revolution with axisymmetric supports
// has modes of the form (family "cos"; the "sin" family, turned by pi/2n,
// has the same frequencies for n >= 1):
//   u_r = U(r, z) cos n theta,  u_theta = -V(r, z) sin n theta,  u_z = W(r, z) cos n theta
// and for n = 0 u_theta = -V(r, z) (torsion). Integrating over theta turns
// the 3D energies into 2D integrals weighted by pi (n >= 1) or 2 pi (n = 0),
// so each n is an independent 2D problem with the U, V, W of the section
// nodes as unknowns (Zienkiewicz & Taylor, vol. 1, ch. 9; Bathe, sec. 5.3).
// The minus sign on V makes a lateral translation X of the n = 1 family read
// U = V = X, so nodes on the axis are held by plain equalities
// (docs/theory/harmonic.md).
//
// Strains in the Voigt order of material.hpp (rr, tt, zz, tz, rz, rt), with
// the theta factor of each row dropped (c for rr, tt, zz, rz; s for tz, rt):
//   e_rr = U,r              e_tt = (U - n V) / r      e_zz = W,z
//   g_tz = V,z + n W / r    g_rz = U,z + W,r          g_rt = V,r - V / r + n U / r
// An orthotropic C never couples a c-row with an s-row, so the signs the
// dropped factors carry cancel in the energy.
#pragma once

#include "material/material.hpp"

#include <Eigen/Dense>

namespace coremodal {

// Node coordinates (r, z) of a quad8 in gmsh order: corners (-1,-1), (1,-1),
// (1,1), (-1,1), then mid-edges (0,-1), (1,0), (0,1), (-1,0); xi along r,
// eta along z for the generated section.
using Quad8Coords = Eigen::Matrix<double, 8, 2>;
using Quad8Matrix = Eigen::Matrix<double, 24, 24>;  // node-major (U, V, W)

// Theta integral of cos^2 n theta (and sin^2 for n >= 1): pi, or 2 pi for n = 0.
double harmonic_weight(int n);

// Quad8 serendipity shape functions and their reference derivatives.
Eigen::Matrix<double, 8, 1> quad8_values(double xi, double eta);
Eigen::Matrix<double, 8, 2> quad8_gradients(double xi, double eta);

struct HarmonicMatrices {
    Quad8Matrix K, M;
    double mass = 0;  // rho times the revolved volume, kg (the whole ring, any n)
};

// Stiffness and consistent mass of one section cell for wave number n, full
// 3 x 3 Gauss integration (the hex20's rule in r and z). Throws SolveError
// for a cell with a non-positive Jacobian or a node at r < 0.
HarmonicMatrices harmonic_quad8_matrices(const Quad8Coords& x, const Matrix6& C, double density, int n);

// The spin coupling of one section cell (effects/rotation.hpp, docs/theory/rotation-harmonic.md):
// a body of revolution spinning at Omega about z, seen from the stationary
// frame, moves its material through every point at Omega d/dtheta, so its
// kinetic energy has the cross term Omega int rho u' . L u dV, L u = d u /
// d theta in Cartesian components = (u_r,t - u_t, u_t,t + u_r, u_z,t) in
// cylindrical ones. For wave number n >= 1 L takes the cos family to the
// sin family: with the pair's amplitudes (a, b), u = a phi_cos + b phi_sin,
// the cross term is Omega (a'^T Gamma b - b'^T Gamma a), and Gamma =
// w_n int rho N^T L_n N r dr dz with L_n = [[n, -1, 0], [-1, n, 0], [0, 0, n]]
// on (U, V, W) is symmetric. For n = 0 L stays in the one family: L_0 =
// [[0, 1, 0], [-1, 0, 0], [0, 0, 0]] (radial against tangential motion) and
// the matrix returned is skew. Either way the gyroscopic matrix per unit
// spin is twice the skew form of the cross term: G = 2 [[0, Gamma], [-Gamma,
// 0]] on (a, b) for n >= 1, G = 2 Gamma_0 for n = 0.
Quad8Matrix harmonic_quad8_spin_coupling(const Quad8Coords& x, double density, int n);

// The centrifugal prestress of a spinning section (effects/rotation.hpp):
// the stress of the axisymmetric (n = 0) static solve under the body force
// rho r e_r per unit Omega^2, at each of a cell's 3 x 3 Gauss points, in the
// order (rr, tt, zz, rz) (the shears tz, rt are those of torsion and stay
// zero under a radial load). Pa per (rad/s)^2.
using SectionStress = Eigen::Matrix<double, 4, 9>;

// The body force rho r e_r per unit Omega^2 of one cell on its (U, V, W)
// nodal values for n = 0: 2 pi int rho N_a r (1, 0, 0) r dr dz.
Eigen::Matrix<double, 24, 1> harmonic_quad8_centrifugal_load(const Quad8Coords& x, double density);

// The n = 0 stress C eps of the cell's nodal displacements u (U, V, W per
// node) at its Gauss points, as SectionStress.
SectionStress harmonic_quad8_stress(const Quad8Coords& x, const Matrix6& C, const Eigen::Matrix<double, 24, 1>& u);

// K_Omega of one cell for wave number n, on one family (the sin family's is
// the same): the geometric stiffness of the prestress sigma_1 less the
// convective softening M_L (effects/rotation.hpp),
//     w_n int [ sum_k grad N^T S grad N (component k) + (sigma_tt / r^2 - rho) N^T L_n^T L_n N ] r dr dz,
// S = [[s_rr, s_rz], [s_rz, s_zz]] on (d/dr, d/dz), L_n as in the spin
// coupling: |L_n (U, V, W)|^2 = (n U - V)^2 + (U - n V)^2 + n^2 W^2 is
// r^2 |grad u|^2 around the circumference and |d u / d theta|^2 both
// (n = 0: U^2 + V^2). A thin free ring has sigma_tt = rho r^2: the two cancel.
Quad8Matrix harmonic_quad8_centrifugal(const Quad8Coords& x, double density, const SectionStress& sigma, int n);

// A distributed spring along a straight 3-node section edge (ends a, b and
// middle node m, in the order a, b, m), stiffness per unit revolved area
// diag(k_r, k_theta, k_z) on (U, V, W): returns the 9 x 9 matrix
// w_n * int N_a N_b diag(k) r ds.
Eigen::Matrix<double, 9, 9> harmonic_edge_spring(const Eigen::Matrix<double, 3, 2>& x, const Eigen::Vector3d& k, int n);

}  // namespace coremodal
