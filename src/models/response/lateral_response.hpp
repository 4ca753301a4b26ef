// The steady forced response of a spinning beam network to loads turning at
// omega = k Omega (docs/theory/response.md), on its lateral problem (both bending
// planes; G couples them):
//
//     (K - omega^2 M + i omega (Omega G + D) + i H) x = f,   q = Re(x e^{i omega t})
//
// (H: the imaginary stiffness, a loss independent of frequency; which damping
// gives it: effects/damping.hpp)
//
// two ways, which check each other:
//  - modal superposition in the modes at rest (K phi = lambda M phi,
//    M-orthonormal, every one of them: beam/rotating_modes dense_modes_at_rest),
//    with the gyroscopic coupling projected, x = Phi_n eta,
//        (Lambda_n - omega^2 I + i omega (Omega Gh_n + Dh_n)) eta = Phi_n^T f,
//    Gh = Phi^T G Phi (skew), Dh = diag(c_j) (effects/damping.hpp): c_j =
//    2 zeta_j omega_j for a mode with a ratio, alpha + beta lambda_j for
//    Rayleigh's (diagonal in the modes at rest either way);
//    with the n lowest modes (truncated) or all of them (exact). A truncated
//    sum may add the static part of the modes left out, Phi_r Lambda_r^-1
//    Phi_r^T f (the mode-acceleration correction), which is what the left-out
//    modes do far below their frequencies;
//  - the direct solve of the full system (Eigen dense LU), with the damping
//    as a matrix: D = alpha M + beta K + M Phi diag(c_j - alpha - beta
//    lambda_j) Phi^T M (pure alpha M + beta K when Rayleigh damps every mode,
//    M Phi Dh Phi^T M when ratios do).
// With the complete basis both are the same linear system in other
// coordinates: they agree to round-off (tests/unit/analyses/response).
//
// A truncated basis (the second constructor: only the modes up to a cutoff,
// from the network's own Krylov solver, complete below it by the inertia
// count) gives the same truncated sums in milliseconds instead of a dense
// eigensolve of every mode: the static part of the modes left out is then
// K^-1 f - Phi_n Lambda_n^-1 Phi_n^T f, the same sum in other terms (K factored
// once, sparse). No complete sum exists then; the direct solve is the sparse
// LU of K - omega^2 M + i omega Omega G (+ i H, Rayleigh's part) with the kept
// modes' own damping M Phi_n diag(c_j - ...) Phi_n^T M by Woodbury's identity
// (the modes left out undamped, as the truncated sum's static part): what
// `coremodal limits`' one light check compares the truncated sum with, as
// the harmonic level's check does (analyses/limits).
#pragma once

#include "beam/beam_network.hpp"
#include "effects/damping.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <memory>
#include <optional>
#include <vector>

namespace coremodal {

class LateralResponse {
public:
    // The static part of the modes left out is K^-1's, without their loss i H (set_imaginary_stiffness).
    static constexpr bool kStaticPartKeepsLoss = false;
    // lambda_scale: the first elastic eigenvalue's scale (rad^2/s^2,
    // eigenvalue_scale.hpp); zeta: the relative damping of every elastic mode
    // (set_damping replaces it). Throws SolveError when the network has no bending DOF.
    LateralResponse(const BeamNetwork& network, double lambda_scale, double zeta = 0);
    // The truncated basis: every lateral mode up to omega_cut (rad/s), and at
    // least the lowest two; std::nullopt where the network's solver cannot
    // prove it complete or K is singular (a free rotor: rigid modes), for
    // the caller to take the complete basis.
    static std::optional<LateralResponse> truncated(const BeamNetwork& network, double lambda_scale, double omega_cut,
                                                    double tolerance);
    // false: the truncated basis (no complete sum, no direct solve).
    bool complete() const { return complete_; }
    // The lateral problem's size: every mode it has, kept or not.
    int n_all_modes() const { return static_cast<int>(m_.K.rows()); }

    // The damping: Rayleigh's alpha M + beta K for every mode whose zeta[j]
    // is empty, 2 zeta[j] omega_j for the others (0 for a rigid mode, which
    // has no frequency to damp at). zeta has n_modes() entries.
    void set_damping(const RayleighDamping& rayleigh, const std::vector<std::optional<double>>& zeta);
    // The imaginary stiffness H on the rows (a loss independent of
    // frequency; effects/damping.hpp builds it): i H in the direct solve,
    // i Phi^T H Phi in the modal equations; the static part of the modes left
    // out stays K^-1's (a loss H = h K changes it by 1/(1 + i h): in magnitude
    // by about h^2/2, 0.02 % at h = 0.02).
    void set_imaginary_stiffness(Eigen::SparseMatrix<double> H);
    // Phi^T H Phi on the basis (project_on_modes; empty without H).
    const Eigen::MatrixXd& imaginary_stiffness_on_modes() const { return Hhat_; }

    int n_modes() const { return static_cast<int>(lambda_.size()); }
    // How many modes lie at or below omega_cut (rad/s): the truncated basis.
    int modes_below(double omega_cut) const;
    double mode_frequency_hz(int j) const;
    double eigenvalue(int j) const { return lambda_(j); }
    // Mode j's relative damping c_j / (2 omega_j) (0 for a rigid mode).
    double modal_damping_ratio(int j) const;
    const NetworkMatrices& matrices() const { return m_; }  // K, M and the rows' network DOFs

    // A network vector (6 DOFs per node) on the problem's rows, and back
    // (zero where held or outside the lateral problem).
    Eigen::VectorXcd to_rows(const Eigen::VectorXcd& network) const;
    Eigen::VectorXcd to_network(const Eigen::VectorXcd& rows) const;
    Eigen::VectorXd mode_shape(int j) const;       // mode j per network DOF
    Eigen::VectorXd mode_mass_shape(int j) const;  // M times it, per network DOF

    // x on the rows for the load f on the rows, at spin Omega and load
    // frequency omega (rad/s), by superposition of the n lowest modes (n =
    // n_modes(): exact), with the static part of the others when asked.
    // K_inverse_f: K^-1 f when the caller has it (a sweep's load is
    // c + Omega^2 p: K^-1 c and K^-1 p once for every speed, static_solve).
    Eigen::VectorXcd superpose(const Eigen::VectorXcd& f, double omega_spin, double omega, int n,
                               bool static_correction = false, const Eigen::VectorXcd* K_inverse_f = nullptr) const;
    // K^-1 f on the rows by the factor of K; none without one (the complete
    // basis of a free rotor).
    std::optional<Eigen::VectorXcd> static_solve(const Eigen::VectorXcd& f) const;
    // The modal coordinates eta of that sum (which mode answers).
    Eigen::VectorXcd modal_coordinates(const Eigen::VectorXcd& f, double omega_spin, double omega, int n) const;
    // The same by the direct solve of the full system: dense with the
    // complete basis, sparse with Woodbury's identity with the truncated one.
    Eigen::VectorXcd direct(const Eigen::VectorXcd& f, double omega_spin, double omega) const;
    // K^-1 f (a static load on the rows), from the complete basis.
    Eigen::VectorXd static_response(const Eigen::VectorXd& f) const;

private:
    LateralResponse(const BeamNetwork& network, double lambda_scale, NetworkMatrices lateral);
    void project_gyroscopic();
    Eigen::VectorXcd sparse_direct(const Eigen::VectorXcd& f, double omega_spin, double omega) const;

    const BeamNetwork* network_;
    double lambda_scale_;
    NetworkMatrices m_;
    Eigen::SparseMatrix<double> G_;  // per unit Omega (rad/s)
    Eigen::MatrixXd Phi_, Ghat_;
    Eigen::VectorXd lambda_, modal_damping_;  // lambda_j; c_j = Phi_j^T D Phi_j
    Eigen::MatrixXd D_;                        // the damping matrix, for the direct solve (complete basis)
    Eigen::VectorXd own_damping_;              // c_j less Rayleigh's part (the truncated basis' direct solve)
    RayleighDamping rayleigh_;
    Eigen::SparseMatrix<double> H_;            // the imaginary stiffness (empty: none)
    Eigen::MatrixXd Hhat_;                     // Phi^T H Phi
    bool complete_ = true;
    std::shared_ptr<const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> K_factor_;  // truncated basis
};

}  // namespace coremodal
