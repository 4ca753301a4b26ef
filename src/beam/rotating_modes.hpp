// The modes of a spinning beam network (effects/rotation.hpp, docs/theory/rotation.md):
//
//     M q'' + Omega G q' + K q = 0,   q = x e^{i omega t}:   (K + i omega Omega G - omega^2 M) x = 0
//
// a quadratic eigenproblem in omega, solved densely (Eigen) by an exact
// linearization. Per independent problem (the bending families together:
// G couples the two planes), once: every mode of K phi = lambda M phi,
// M-orthonormal (Phi, Lambda = diag lambda). In those coordinates, x = Phi eta,
//     omega^2 eta = i omega Omega Gh eta + Lambda eta,   Gh = Phi^T G Phi (skew),
// and with z = (omega eta, Lambda^1/2 eta) this is the Hermitian eigenproblem
//     H z = omega z,   H = [[i Omega Gh, Lambda^1/2], [Lambda^1/2, 0]]   (size 2n)
// whose eigenvalues are real and come in pairs +-omega (x and its conjugate):
// the positive ones are the natural frequencies at that speed. The basis is
// complete (all n modes), so nothing is truncated; at Omega = 0, H's
// eigenvalues are +-sqrt(lambda): the modes at rest.
//
// Completeness: H is Hermitian and solved whole, so all 2n eigenvalues are
// found; the modes of K with lambda ~ 0 (rigid) stay modes at every speed
// (K x = 0 solves the quadratic problem at omega = 0) and are reported once,
// at 0 Hz. Every mode's residual is computed on the quadratic problem itself.
//
// Whirl: the orbit of a node is Re(x e^{i omega t}); (x, y) turns with the
// spin (+z, forward) when Im(ux conj(uy)) > 0. The circularity
// c = 2 sum Im(ux conj uy) / sum (|ux|^2 + |uy|^2) over the network's nodes
// is +1 for a forward circle, -1 for a backward one, 0 for a planar mode.
#pragma once

#include "beam/beam_network.hpp"
#include "beam/timoshenko_element.hpp"
#include "modes/mode_set.hpp"
#include "modes/rotating_mode.hpp"

#include <Eigen/Dense>

#include <optional>
#include <vector>

namespace coremodal {

// The gyroscopic matrix per unit spin speed of a Timoshenko element spinning
// about z (effects/rotation.hpp): int rho_J N_a N_b dz on (rx_a, ry_b), its
// negative on (ry_a, rx_b); skew-symmetric, interpolated like the rotary mass.
BeamElementMatrix element_gyroscopic(const TimoshenkoElement& e);

// G per unit spin speed (rad/s) of each problem, on its rows (its free_dofs):
// every beam of the network spins (a roll network's beams are the core and
// the chucks' bodies and shafts); springs and point masses (bearings,
// frames) add nothing.
std::vector<Eigen::SparseMatrix<double>> assemble_gyroscopic(const BeamNetwork& network,
                                                             const std::vector<NetworkMatrices>& problems);

// The label of a mode of the network (rigid, bending n = 1, axial, torsion,
// mixed; m = sign changes along the core) from its shape and M times it, per
// network DOF (beam/beam_model.cpp: the beam level's one labelling).
ModeLabel label_beam_mode(const BeamNetwork& network, const Eigen::VectorXd& shape, const Eigen::VectorXd& mass_shape,
                          double eigenvalue, double lambda_scale);

// The family set of the network's lateral motion: every independent set
// that bends, merged (G couples the two bending planes); 0 without bending.
FamilySet lateral_family_set(const BeamNetwork& network);

// Every mode at rest of one assembled problem, K phi = lambda M phi, dense:
// Phi M-orthonormal, lambda ascending (rad^2/s^2). lambda_scale (rad^2/s^2)
// sets the negative shift that keeps the lowest modes accurate to round-off
// relative to themselves. Throws SolveError when K - sigma M is not
// positive definite.
struct DenseModes {
    Eigen::MatrixXd Phi;
    Eigen::VectorXd lambda;
};
DenseModes dense_modes_at_rest(const NetworkMatrices& problem, double lambda_scale);

class RotatingNetwork {
public:
    // lambda_scale: the scale of the first elastic eigenvalue (rad^2/s^2),
    // which says what is rigid (eigenvalue_scale.hpp).
    RotatingNetwork(const BeamNetwork& network, double lambda_scale);

    // The lowest `max_modes` modes at spin speed f_rot (Hz, >= 0), ascending
    // in frequency: rigid modes first (0 Hz), then the positive frequencies.
    // (All of them are computed; only the ones returned get a shape, label
    // and residual.)
    std::vector<RotatingMode> modes_at(double speed_hz, int max_modes) const;

    long n_free_dofs() const { return n_free_dofs_; }

private:
    struct Problem {
        NetworkMatrices m;
        Eigen::SparseMatrix<double> G;  // per unit Omega (rad/s)
        bool spins = false;             // G has entries
        Eigen::MatrixXd Phi;            // M-orthonormal modes at rest
        Eigen::VectorXd lambda;         // ascending
        Eigen::MatrixXd Ghat;           // Phi^T G Phi
        double norm_K = 0, norm_M = 0, norm_G = 0;
        // The x-z bending plane standing for both (the planes alike): in
        // u = ux + i uy the problem is K a - omega^2 M a + omega Omega G a = 0
        // with G = rho_J N N on ry (symmetric) and omega > 0 forward, < 0
        // backward whirl: real, half the size (docs/theory/rotation.md).
        bool plane = false;
    };
    // How a candidate's rows become network DOFs: as they are, or from the
    // x-z plane: planar in x-z, planar in y-z, or whirling (the sign of omega).
    enum class Kind { rows, planar_x, planar_y, whirl };
    // A mode before its shape is finished: its problem, omega and eta.
    struct Candidate {
        const Problem* problem;
        double omega;  // signed for Kind::whirl
        Eigen::VectorXcd eta;
        Kind kind = Kind::rows;
    };
    void add_plane_candidates(const Problem& p, double omega_spin, std::vector<Candidate>& out) const;
    Eigen::VectorXcd network_shape(const Problem& p, const Eigen::VectorXcd& x, Kind kind, double omega) const;
    void add_candidates(const Problem& p, double omega_spin, std::vector<Candidate>& out) const;
    RotatingMode finish(const Candidate& c, double omega_spin) const;

    const BeamNetwork* network_;
    double lambda_scale_;
    long n_free_dofs_ = 0;
    std::vector<Problem> problems_;
};

// The critical speeds of a network whose bending planes are alike, exactly
// and without a sweep: where the excitation line f = order f_rot meets a
// forward (omega = +order Omega) or backward (omega = -order Omega) whirl,
// the plane problem K a - omega^2 M a + omega Omega G a = 0 becomes the
// symmetric pencil
//     K a = Omega^2 (order^2 M -+ order G) a,
// one dense generalized eigensolve per order and whirl (K positive
// definite: a roll held in its stand). Every crossing of the Campbell
// diagram up to max_speed_hz, ascending, each labelled from its shape
// (label_beam_mode of the planar snapshot). std::nullopt when the planes
// differ (the sweep then) or K is singular (rigid modes).
struct PlaneCrossing {
    int order = 1;
    Whirl whirl = Whirl::forward;
    double speed_hz = 0;  // f_rot
    ModeLabel label;
};
std::optional<std::vector<PlaneCrossing>> plane_critical_speeds(const BeamNetwork& network, double lambda_scale,
                                                                const std::vector<int>& orders, double max_speed_hz);

}  // namespace coremodal
