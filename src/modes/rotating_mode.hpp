// A mode of a spinning rotor at one speed, at any model level (the beam
// network, the harmonic level's wave numbers, the solid): its frequency,
// whirl, label and complex shape, and the MAC of two complex shapes that
// tracks it from speed to speed (analyses/campbell, response, limits).
#pragma once

#include "modes/mode_set.hpp"

#include <Eigen/Dense>

namespace coremodal {

// none: no orbit to speak of (standing still, axial, torsion, rigid).
enum class Whirl { none, forward, backward };
const char* whirl_name(Whirl w);  // "", "FW", "BW"

// Below this |circularity| a lateral mode is planar: no whirl (at rest, or
// held much stiffer in one plane than the other).
constexpr double kPlanarCircularity = 1e-6;

struct RotatingMode {
    double frequency_hz = 0;  // >= 0
    Whirl whirl = Whirl::none;
    double circularity = 0;
    ModeLabel label;  // of the mode's largest real snapshot (label_beam_mode)
    // ||(K + i omega Omega G - omega^2 M) x|| / ((||K|| + omega Omega ||G|| + omega^2 ||M||) ||x||)
    double relative_residual = 0;
    Eigen::VectorXcd shape;  // per network DOF (6 per node), x^H M x = 1, zero where held
    // Which independent problem the shape's DOFs belong to: modes of
    // different blocks never match by MAC (the harmonic level: the wave
    // number n; the beam network: 0, one vector for all).
    int block = 0;
};

// |x^H y|^2 / (|x|^2 |y|^2): the MAC of two complex shapes (1: the same
// mode up to a complex factor).
double complex_mac(const Eigen::VectorXcd& x, const Eigen::VectorXcd& y);

}  // namespace coremodal
