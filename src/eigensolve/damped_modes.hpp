// Complex modes of a damped, spinning model in a modal basis (dense): the
// projected quadratic eigenproblem with the damping terms the scene names,
//
//     (lambda^2 M + lambda (D + Omega G) + K + i H) x = 0,
//
// D viscous (Term::damping: Rayleigh's alpha M + beta K, modal ratios as
// M Phi diag(2 zeta_j omega_j) Phi^T M), G gyroscopic per unit spin (skew),
// H the imaginary part of a complex stiffness (Term::imaginary_stiffness:
// a loss independent of frequency; effects/damping.hpp says which damping
// gives it). A free vibration x e^{lambda t} of a mode of
// natural frequency omega and ratio zeta has
//
//     lambda = -zeta omega +- i omega sqrt(1 - zeta^2),
//
// so omega = |lambda| and zeta = -Re(lambda) / |lambda| (Meirovitch,
// Fundamentals of Vibrations, 2001, ch. 2; any vibration text).
//
// The imaginary stiffness is linearised as the complex stiffness K + i H itself,
// in the state space (no equivalent viscous C = H / omega iterated per mode):
// exact at every frequency for a loss that does not depend on frequency.
// Its eigenvalues are not in conjugate pairs: with K + i H only the roots of
// positive frequency (Im lambda > 0) are the physical ones, the others grow
// (the complex stiffness is not causal in the time domain; Crandall, "The
// role of damping in vibration theory", J. Sound Vib. 11(1) 3-18, 1970);
// their partners of negative frequency are the conjugates, roots of
// K - i H. A single mode with h = phi^T H phi / phi^T K phi then has
// lambda = i omega sqrt(1 + i h): zeta = sin(atan(h) / 2), h / 2 to
// first order, and |lambda| = omega (1 + h^2)^(1/4). So every mode is reported once, by its
// root of positive frequency; without H that is the usual half of the
// conjugate pairs. Roots on the real axis (overdamped, or rigid) have no
// frequency to report and are counted only.
//
// Solved whole (Eigen's complex Schur form of the first companion
// linearisation, size 2m; Tisseur & Meerbergen, "The quadratic eigenvalue
// problem", SIAM Review 43(2) 235-286, 2001, sec. 3.4): the basis is small
// (the kept modes), and every root is found, so the set is complete by
// construction. The damped problem is not Hermitian: no inertia count
// proves a band (gyroscopic_inertia.hpp is for the undamped pencil); each
// mode carries instead its backward error on the projected problem,
// ||Q(lambda) x|| / ((||K + i H|| + |lambda| ||D + Omega G|| + |lambda|^2 ||M||) ||x||)
// (Tisseur, Linear Algebra Appl. 309, 339-361, 2000), for the caller to
// check as the residual of a mode of the full set is checked.
#pragma once

#include <Eigen/Dense>

#include <complex>
#include <vector>

namespace coremodal {

// The operators of a model projected on a basis V (dense, m x m; D, G and H
// empty when the model has no such term). With an M-orthonormal basis of
// modes at rest, M = I and K = diag(lambda_j).
struct ProjectedDampedModel {
    Eigen::MatrixXd K, M;
    Eigen::MatrixXd G;  // per unit spin (rad/s), skew
    Eigen::MatrixXd D;  // viscous damping
    Eigen::MatrixXd H;  // the stiffness' imaginary part (Term::imaginary_stiffness)
};

// V^T A V: a term of the full model projected on a basis (A dense or sparse).
template <class Matrix>
Eigen::MatrixXd project_term(const Matrix& A, const Eigen::MatrixXd& V) {
    return V.transpose() * (A * V);
}

struct DampedMode {
    std::complex<double> eigenvalue;  // lambda (1/s), Im lambda > 0
    double natural_frequency_hz = 0;  // |lambda| / (2 pi)
    double damped_frequency_hz = 0;   // Im lambda / (2 pi): what a Campbell diagram plots
    double zeta = 0;                  // -Re lambda / |lambda| (< 0: the mode grows)
    Eigen::VectorXcd shape;           // x in the basis' coordinates, unit 2-norm
    double backward_error = 0;        // on the projected problem, above
};

struct DampedModes {
    std::vector<DampedMode> modes;  // ascending damped frequency
    int n_non_oscillating = 0;      // roots on the real axis (|Im lambda| <= the floor: overdamped or rigid)
};

// The complex modes of `model` at spin `spin` (rad/s). `frequency_floor`
// (rad/s): a root with Im lambda at or below it is not an oscillating mode
// (the caller's rigid line). Throws SolveError when M is not positive definite.
DampedModes damped_modes(const ProjectedDampedModel& model, double spin, double frequency_floor);

}  // namespace coremodal
