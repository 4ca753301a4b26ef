// What each model level is and can do, in one table: the analyses ask a
// level's traits (can it spin, carry a forced response, give sensitivities,
// run a converge ladder; which refusal to give) and the writers take its
// words (a display name, how its DOFs and problems are counted), never
// comparing a level's name. models/choose.hpp picks the level. The table is
// data about the levels, not their code (models/<level>/), so that every
// layer can read it, the writers in output/ included; docs/architecture.md
// says how to add a level.
#pragma once

#include "scene/model_choice.hpp"

#include <string>

namespace coremodal {

struct LevelTraits {
    ModelChoice level;
    const char* title;  // "Beam", "Harmonic", ...: report headings
    // Bodies of revolution only (the harmonic level: one 2D problem per wave
    // number n); require_axisymmetric says why a scene is not one.
    bool axisymmetric_only;
    // Spinning (campbell, response, limits): the gyroscopic terms exist.
    // Where not, `why_not_spinning` says why.
    bool spins;
    const char* why_not_spinning;
    // The solid spins any scene in co-rotating coordinates, and refuses
    // what it cannot (models/solid/rotating_solid.hpp: require_spinnable_by_solid).
    bool spins_in_rotating_frame;
    // The centrifugal (prestress) stiffening of a spinning body (effects/rotation.hpp).
    bool centrifugal;
    // The forced response's gyroscopic term is the stationary frame's, right
    // for a body of revolution only (docs/theory/rotation.md): the solid refuses the
    // others; the harmonic level is one, the beam network has no section.
    bool response_needs_revolution;
    // The exact critical speeds of a pencil of two bending planes (beam/speeds.hpp).
    bool pencil_critical_speeds;
    // Through-wall shear (G_rz) in the model: not in a beam's section.
    bool through_wall_shear;
    // d ln f / d ln p from the assembled operators (analyses/sensitivity, fit).
    bool sensitivities;
    // A refinement ladder in `coremodal converge`, and whether it is the
    // reference the others' model error is measured against (the solid).
    bool converge_ladder;
    bool converge_reference;
    // Solved on a mesh of the case's mesh level (not the beam network).
    bool meshed;
    // [damping] as terms of the operator sets along a Campbell sweep (the
    // damped modes: models/harmonic/rotating_harmonics.hpp).
    bool campbell_damping;
    // The run report's words for its DOFs and its independent problems.
    const char* dofs_counted;     // "DOFs", "DOFs per wave number n"
    const char* problems_line;    // before the per-problem list ("" for one problem)
    const char* inertia_counts;   // how the problems' inertia counts add up
    const char* count_owners;     // whose counts are summed, in the console line
    // The forced response's report: its heading and the direct equation it is checked against.
    const char* response_heading;
    const char* response_equation;
};

// The traits of a resolved level (not ModelChoice::automatic: chosen_level resolves it).
const LevelTraits& level_traits(ModelChoice level);

}  // namespace coremodal
