// The modes of a winder model at one roll diameter, verified, named by the
// body that carries them, damped, and the response at a drum's centre.
//
// 1. Solve: the reduced problem is a few hundred DOFs, so a dense generalized
//    solve (Eigen::GeneralizedSelfAdjointEigenSolver; M is positive definite:
//    every DOF has mass or rotary inertia) gives every mode, M-normalised.
// 2. Verify the reported modes (up to max_frequency): residuals
//    ||K x - lambda M x|| / (||K|| ||x||), M-orthonormality, and the number
//    of eigenvalues below a shift in the gap after the last one by the
//    inertia of K - sigma M (Sylvester, sparse LDL^T): none missed.
// 3. Name: the kinetic energy of a mode shared among drums, rolls and rider
//    (M is block-diagonal by body); the largest share names the mode.
// 4. Damp: modal strain energy: zeta_i = sum_c zeta_c U_c,i / U_i, with U_c
//    the strain energy of the drums (bending and bearings), the rider (bending
//    and supports) and the nips (springs, and a roll beam's own bending).
// 5. Respond: X/F at a drum's mid-span by modal superposition over all modes,
//    H(w) = sum_i x_i(p)^2 / (w_i^2 - w^2 + 2 i zeta_i w_i w)   (m/N).
#pragma once

#include "modes/mode_set.hpp"  // Verification
#include "winder/winder_model.hpp"

#include <Eigen/Dense>

#include <array>
#include <complex>
#include <vector>

namespace coremodal {

struct WinderMode {
    double eigenvalue = 0;  // rad^2/s^2
    double frequency_hz = 0;
    BodyKind type = BodyKind::drum;
    std::array<double, kBodyKinds> kinetic_share{};  // drums, rolls, rider (sum 1)
    double damping_ratio = 0;
    double relative_residual = 0;
};

struct WinderModes {
    std::vector<WinderMode> modes;  // every mode of the model, ascending
    int n_reported = 0;             // modes up to max_frequency (verified, named, tracked)
    Eigen::MatrixXd shapes;         // reduced DOFs x modes, M-normalised
    Verification verification;      // of the reported modes
};

WinderModes solve_winder_modes(const WinderModel& model, const WinderDamping& damping, double max_frequency_hz);

// X/F (m/N, complex) at reduced DOF `dof` for a harmonic force there.
std::complex<double> receptance(const WinderModes& modes, int dof, double frequency_hz);

// The reduced DOF of a drum's mid-span translation in a direction.
int response_dof(const WinderModel& model, DrumSide drum, ResponseDirection direction);

// A mode reduced to the translations (ux, uy) of every network node, for MAC
// between roll diameters: the DOFs are the same at every diameter.
std::vector<double> mode_signature(const WinderModel& model, const Eigen::VectorXd& shape);

}  // namespace coremodal
