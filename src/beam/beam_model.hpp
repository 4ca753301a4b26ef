// The beam model level (model = "beam", docs/theory/beam.md): a scene as a network
// of Timoshenko beams on the z axis, solved in well under a millisecond.
//
//   core + rest paper  one beam over the core length (composite section, BeamSection)
//   rigid clamp zone   the core nodes in the zone held (all six DOFs)
//   chuck              a steel beam of its own: shaft (bearing to core end) and body
//                      (core end to inserted_length), on the same z stations as the core
//   expanding element  spring interface: a distributed spring layer between core and
//                      chuck body over the element's width (per-length stiffness from
//                      k_n, k_t integrated over its band or segments); bonded: the body
//                      shares the core's nodes over the width (a tie, no penalty)
//   bearing            rigid: the shaft end held; elastic: radial and tilting springs
//                      to ground, or the radial spring to a frame mass on a frame spring
//
// What a beam cannot see: cross-section deformation (ovalling, breathing), the
// wall's through-thickness shear (G_rz) and the local compliance of a clamp or
// chuck edge on a shear-soft wall. docs/theory/beam.md says when the model holds.
#pragma once

#include "beam/beam_network.hpp"
#include "effects/support_effects.hpp"
#include "modes/mode_set.hpp"
#include "scene/scene.hpp"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace coremodal {

struct BeamModelOptions {
    // Three-node elements along the core length; support, chuck and
    // expanding-element edges add some. 30 puts the first 20 modes of case
    // 05's rest roll, clamped or on chucks, within 0.1 % of a mesh ten times
    // finer (tests/unit/beam/test_beam_model.cpp).
    int core_elements = 30;
    // Uniform refinement of that mesh (`coremodal converge`'s beam ladder):
    // every gap between support edges and every chuck shaft gets exactly
    // `refine` times the elements core_elements gives it (minimums included),
    // so the element lengths are exactly 1/refine of the unrefined ones.
    int refine = 1;
    bool force_dense = false;  // tests: dense eigensolver whatever the size
};

struct BeamMode {
    double eigenvalue = 0;  // rad^2/s^2
    double frequency_hz = 0;
    ModeLabel label;  // rigid, bending (n = 1), axial, torsion (n = 0), mixed; m = sign changes along the core
    EffectiveMass effective_mass;
    double relative_residual = 0;
    // Per network node, (ux, uy, uz, rx, ry, rz); M-normalised, zero at held DOFs.
    Eigen::VectorXd shape;
};

struct BeamModelTiming {
    double build = 0;     // s, the network from the scene
    double solve = 0;     // s, assembly by problem, eigensolve, inertia check
    double classify = 0;  // s, labels and effective masses
};

struct BeamModelResult {
    BeamNetwork network;  // beam 0 is the core; then the chucks, left and right
    std::vector<BeamMode> modes;
    Verification verification;
    long n_dofs = 0;          // free DOFs
    long n_held_nodes = 0;    // nodes with all six DOFs held
    double lambda_scale = 0;  // rad^2/s^2: the scale of the first elastic eigenvalue (eigenvalue_scale.hpp)
    int n_problems = 0;       // independent eigenproblems (network_modes.hpp)
    bool mirrored_planes = false;
    bool dense_retry = false;  // the inertia check failed once and every problem was solved densely
    // What this model assumed beyond the scene (e.g. how an elastic bearing
    // holds the shaft axially), for the run summary.
    std::vector<std::string> assumptions;
    BeamModelTiming timing_s;
};

// The network of a scene, and the assumptions made building it.
BeamNetwork build_beam_network(const Scene& scene, const BeamModelOptions& options,
                               std::vector<std::string>* assumptions = nullptr);

// The spring layer (effects/support_effects.hpp) at the beam level: its
// stiffness per unit length (6x6 on ux, uy, uz, rx, ry, rz) at radius R
// between a chuck body and the core bore, from the normal and tangential
// stiffness per unit area k_n, k_t (Pa/m) integrated over the element's
// contact arcs (a full band or `segments` pads; docs/theory/beam.md, "Expanding elements").
Matrix6 spring_layer_per_length(const SpringLayer& layer, const ExpandingElement& element, double radius);

// The modes the scene asks for ([analysis] modes or band), no I/O. Throws
// SolveError when the eigensolver fails.
BeamModelResult solve_beam_model(const Scene& scene, const BeamModelOptions& options = {});

}  // namespace coremodal
