// The model levels of a converge study as ladders (models/ladder/model_ladder.hpp:
// each level hands out its own, ModelLevel::converge_ladder) and one run of a
// step with its cost measured around it (wall from the level, processor
// time, PETSc's solver events, peak memory).
#pragma once

#include "analyses/converge/converge.hpp"
#include "analyses/converge/converge_study.hpp"
#include "models/ladder/model_ladder.hpp"

#include <ostream>
#include <vector>

namespace coremodal {

// The ladders of the model levels asked for (--models, in their order:
// solid, beam, harmonic by default) that can solve the scene; the others
// leave a note in study.notes. The scene outlives the ladders.
std::vector<ModelLadder> model_ladders(const Scene& scene, const ConvergeOptions& o, std::ostream& progress,
                                       ConvergeStudy& study);

// One run of a step of the ladder with n_modes modes, measured: its
// processor time, the solver's events and the peak memory over the ranks
// (since a reset where the system allows one, else the process's peak so
// far). Freed memory is handed back to the system afterwards, so that a
// level does not inherit the previous level's heap.
LevelRun measured_run(const ModelLadder& ladder, const MeshStep& step, int n_modes);

}  // namespace coremodal
