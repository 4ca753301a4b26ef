// Steps the solid and harmonic levels share: what the case asks of SLEPc,
// the solve with the case file named in the solver's input errors, a mode
// numbered from its eigenvalue.
#pragma once

#include "eigensolve/modal_solver.hpp"
#include "modes/classify.hpp"
#include "modes/mode_set.hpp"
#include "scene/scene.hpp"

#include <string>

namespace coremodal {

// What the case's [analysis] asks of the eigensolver (beam/eigenvalue_scale.hpp,
// mode_request) with the section families, and SLEPc's iteration limit.
SolveRequest solve_request(const Scene& scene);
// A progress line: which family's estimate set the shift, and its frequency.
std::string shift_scale_text(const Scene& scene);

// solve_modes; its input errors (e.g. more modes than DOFs) are about the
// case file's [analysis] table, so they name the file, then `problem`
// ("" for the whole model, or which of its independent problems).
SolvedModes solve_for_case(const Scene& scene, const OperatorSet& operators, const SolveRequest& request,
                           const Progress& progress, const std::string& problem);

// Whether the roll is held (supports or a web) or a free body: the mode
// classifier names a rigid-body motion at a frequency of its own "support"
// or "rigid" by it (modes/classify.hpp).
BodyHeld body_held(const Scene& scene);

// A mode with its index (from 1), eigenvalue, frequency and residual.
Mode numbered_mode(int index, double lambda, double relative_residual);

}  // namespace coremodal
