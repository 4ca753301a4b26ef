// Modes after the eigen solve, verified, classified and ready to write.
#pragma once

#include "eigensolve/verification.hpp"

#include <string>
#include <vector>

namespace coremodal {

// A mode is "mixed" unless one family holds at least this share of its kinetic energy.
constexpr double kMinDominantShare = 0.5;

// One word per mode: rigid, bending, torsion, axial, breathing, ovalling, mixed.
struct ModeLabel {
    std::string type = "mixed";
    int n = 0;                    // circumferential wave number
    int m = 0;                    // axial nodes (sign changes of the axial profile)
    double dominant_share = 0;    // share of the kinetic energy in the dominant family
};

// Effective modal mass (M-normalised mode): x, y, z in kg; about the z axis in kg m^2.
struct EffectiveMass {
    double x = 0, y = 0, z = 0, rz = 0;
};

struct Mode {
    int index = 0;          // 1-based, in order of frequency
    double eigenvalue = 0;  // omega^2, rad^2/s^2
    double frequency_hz = 0;
    ModeLabel label;
    double relative_residual = 0;  // ||K x - lambda M x|| / (||K|| ||x||)
    EffectiveMass effective_mass;
    // Displacement of every mesh node (n_nodes x 3, node-major), M-normalised;
    // zero at clamped nodes. Held on rank 0 only.
    std::vector<double> shape;
    // Mesh-independent signature for MAC tracking across study points
    // (modes/mac.hpp: layout and meaning); empty when the model gives none.
    // Held on rank 0 only.
    std::vector<double> signature;
};

struct ModeSet {
    std::vector<Mode> modes;
    Verification verification;
};

}  // namespace coremodal
