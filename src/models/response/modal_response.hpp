// The steady forced response of a spinning model given as sparse matrices
// (the harmonic level's wave number n = 1, the solid) to loads turning at
// omega = k Omega (docs/theory/response.md):
//
//     (K - omega^2 M + g omega Omega G + i omega D + i H) x = f
//
// (H: the imaginary stiffness, a loss independent of frequency; which damping
// gives it: effects/damping.hpp)
// with g the gyroscopic unit: i for a model with both planes, where G is
// skew (the solid, as the beam network: effects/rotation.hpp), or 1 for the
// harmonic level's n = 1 as one complex plane. There the two families are
// coupled by G2 = 2 [[0, Gamma], [-Gamma, 0]] (spinning_harmonic.hpp); a
// load turning forward is (p, -i p) on (cos, sin), and its response is
// (a, -i a) with (K - omega^2 M + omega Omega 2 Gamma + i omega D) a = p (the
// second row is the first times -i): the two planes as one complex plane
// u = u_x + i u_y, exactly, for a body of revolution (docs/theory/rotation.md: the
// beam level's plane path is the same).
// Two ways, which check each other:
//  - modal superposition in the n lowest modes at rest (K phi = lambda M
//    phi, M-orthonormal: a basis the caller solved for), with the gyroscopic
//    coupling projected (modal_equations.hpp) and the static part of every
//    other mode, K^-1 f - Phi_n Lambda_n^-1 Phi_n^T f (the mode-acceleration
//    correction; K^-1 from a sparse Cholesky factor (CHOLMOD), so that no
//    complete basis of a mesh is needed);
//  - the direct solve of the full problem (sparse LU, UMFPACK), with the damping as
//    a matrix: D = alpha M + beta K + M Phi diag(c_j - alpha - beta lambda_j)
//    Phi^T M over the basis' modes (Woodbury's identity on the sparse
//    factor); a mode above the basis takes Rayleigh's damping, or none.
// With the complete basis both are the same linear system in other
// coordinates (tests/verification/test_harmonic_response.cpp).
#pragma once

#include "effects/damping.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <complex>
#include <memory>
#include <optional>
#include <vector>

namespace coremodal {

// Modes at rest: M-orthonormal columns, eigenvalues ascending (rad^2/s^2).
struct ModalBasis {
    Eigen::MatrixXd Phi;
    Eigen::VectorXd lambda;
};

// The gyroscopic unit g above.
inline const std::complex<double> kOnePlane{1, 0};   // symmetric G of one complex plane
inline const std::complex<double> kTwoPlanes{0, 1};  // skew G of both planes

class ModalResponse {
public:
    // The static part of the modes above the basis keeps their loss i H (set_imaginary_stiffness).
    static constexpr bool kStaticPartKeepsLoss = true;
    // K, M and G (per unit Omega, rad/s) of the model and its gyroscopic
    // unit; the basis of its lowest modes at rest; lambda_scale: the first
    // elastic eigenvalue's scale (rad^2/s^2), for the rigid line. Throws
    // SolveError when K is singular (a scene free to move has no steady response).
    ModalResponse(Eigen::SparseMatrix<double> K, Eigen::SparseMatrix<double> M, Eigen::SparseMatrix<double> G,
                  std::complex<double> gyroscopic_unit, ModalBasis basis, double lambda_scale);

    // Rayleigh's alpha M + beta K for every basis mode whose zeta[j] is
    // empty (and every mode above the basis), 2 zeta[j] omega_j for the
    // others. zeta has n_modes() entries.
    void set_damping(const RayleighDamping& rayleigh, const std::vector<std::optional<double>>& zeta);
    // The imaginary stiffness H (effects/damping.hpp builds it): i H in
    // the direct solve, i Phi^T H Phi in the modal equations (frequency
    // independent), and the static part of the modes above the basis with
    // their loss: (K + i H)^-1 p less the kept modes' (Lambda_n + i Hh_n)^-1
    // part (complex_static_response then solves with K + i H, factored once).
    void set_imaginary_stiffness(Eigen::SparseMatrix<double> H);
    // Phi^T H Phi on the basis (project_on_modes; empty without H).
    const Eigen::MatrixXd& imaginary_stiffness_on_modes() const { return Hhat_; }

    int n_modes() const { return static_cast<int>(basis_.lambda.size()); }
    long n_dofs() const { return static_cast<long>(K_.rows()); }
    // How many basis modes lie at or below omega_cut (rad/s).
    int modes_below(double omega_cut) const;
    double eigenvalue(int j) const { return basis_.lambda(j); }
    double mode_frequency_hz(int j) const;
    const Eigen::MatrixXd& modes() const { return basis_.Phi; }
    const Eigen::SparseMatrix<double>& stiffness() const { return K_; }
    const Eigen::SparseMatrix<double>& mass() const { return M_; }

    // x for the load p, at spin Omega and load frequency omega (rad/s), by
    // superposition of the n lowest basis modes, with the static part of
    // every other mode when asked.
    Eigen::VectorXcd superpose(const Eigen::VectorXcd& p, double omega_spin, double omega, int n,
                               bool static_correction = false) const;
    // The same with the static part of the others, K^-1 p given (a caller
    // that sweeps a load c + Omega^2 s factors K^-1 c and K^-1 s once).
    Eigen::VectorXcd superpose(const Eigen::VectorXcd& p, double omega_spin, double omega, int n,
                               const Eigen::VectorXcd& static_p) const;
    Eigen::VectorXcd modal_coordinates(const Eigen::VectorXcd& p, double omega_spin, double omega, int n) const;
    // The same by the direct sparse solve of the full problem.
    Eigen::VectorXcd direct(const Eigen::VectorXcd& p, double omega_spin, double omega) const;
    // K^-1 p (a static load).
    Eigen::VectorXd static_response(const Eigen::VectorXd& p) const;
    // K^-1 p, p complex; (K + i H)^-1 p with an imaginary stiffness (the static part of the superposition).
    Eigen::VectorXcd complex_static_response(const Eigen::VectorXcd& p) const;

    // The spins at which a mode of the projected model whirls at
    // omega = order x Omega, forward (direction +1) or backward (-1), for one
    // complex plane (kOnePlane): det(Lambda - omega^2 I + omega Omega Gh) = 0
    // with omega = +-order Omega is the symmetric pencil
    //     Lambda y = Omega^2 (order^2 I -+ order Gh) y,
    // solved as the eigenvalues nu = 1 / Omega^2 of Lambda^-1/2 (order^2 I -+
    // order Gh) Lambda^-1/2 (dense, the basis' size). The crossings of the
    // truncated model, exactly: what its forced response resonates at
    // (docs/how-to/limits.md, "Speed"). Ascending spin (rad/s) up to omega_spin_max,
    // each with its modal coordinates y.
    struct SynchronousCrossing {
        double omega_spin = 0;
        Eigen::VectorXd modal;
    };
    std::vector<SynchronousCrossing> synchronous_crossings(int order, int direction, double omega_spin_max) const;

private:
    Eigen::SparseMatrix<double> K_, M_, G_;
    std::complex<double> gyroscopic_unit_;
    ModalBasis basis_;
    double lambda_scale_;
    Eigen::MatrixXd Ghat_, MPhi_;  // Phi^T G Phi; M Phi
    Eigen::SparseMatrix<double> H_;  // the imaginary stiffness (empty: none)
    Eigen::MatrixXd Hhat_;           // Phi^T H Phi
    Eigen::VectorXd damping_, own_damping_;  // c_j; c_j less Rayleigh's part (the matrix form's low-rank term)
    RayleighDamping rayleigh_;
    struct StiffnessFactor;  // CHOLMOD's, kept out of this header (modal_response.cpp)
    std::shared_ptr<const StiffnessFactor> K_factor_;
    struct ComplexStiffnessFactor;  // UMFPACK's LU of K + i H (with an imaginary stiffness only)
    std::shared_ptr<const ComplexStiffnessFactor> KH_factor_;
};

}  // namespace coremodal
