// The scale of a scene's lowest elastic eigenvalue, for every shape: a long
// core, a ring, a disc, a roll on soft springs (docs/theory/methods.md, "The
// eigenvalue scale").
//
// The eigensolvers need it twice: the negative shift sigma = -c * scale keeps
// K - sigma M positive definite beside rigid-body modes and near the wanted
// modes, and |lambda| < kRigidEigenvalueFraction * scale says "rigid". Both
// only need its order of magnitude, but for every shape: the Euler–Bernoulli
// estimate alone is MHz for a body shorter than its diameter, and every
// elastic mode of a ring then looks rigid.
//
// The scale is the smallest of closed-form estimates, one per family of
// modes. Each is the lowest eigenvalue of a simpler model of that family (the
// Euler–Bernoulli beam, the shear beam, the bar in tension and in torsion, the
// thin ring in and out of its plane, the roll on its springs), which is, or is
// close to, the Rayleigh quotient of a motion the scene's model can make; so
// each lies above the scene's lowest elastic eigenvalue or near it, and the
// smallest is the tightest. Constraints (clamps) only raise eigenvalues.
#pragma once

#include "eigensolve/mode_request.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The families of modes a model level has: the beam network bends, stretches
// and twists (the roll and its supports); the solid and harmonic levels also
// deform the cross-section (ovalling, breathing, a ring's twisting).
enum class ModeFamilies { beam, beam_and_section };

struct EigenvalueEstimate {
    std::string family;  // "bending", "ring in-plane n = 2", ... (progress lines, tests)
    double lambda = 0;   // rad^2/s^2
};

// One estimate per family that the scene and the model level have.
std::vector<EigenvalueEstimate> elastic_eigenvalue_estimates(const Scene& scene, ModeFamilies families);

// The smallest of those estimates.
EigenvalueEstimate elastic_eigenvalue_scale(const Scene& scene, ModeFamilies families);

// What the scene's [analysis] asks of the eigensolver of a level with these
// families: the lowest modes or a band, the residual, and the shift's scale
// from the lowest of the closed-form estimates (the right order for a long
// core, a ring and a disc alike). One rule for every model level.
ModeRequest mode_request(const Scene& scene, ModeFamilies families);

}  // namespace coremodal
