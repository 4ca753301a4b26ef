// The model levels of a converge study as ladders: the steps of each
// (refinement_ladder.hpp) and how to run one step once, with its cost
// measured (wall, CPU, PETSc's solver events, peak memory). These call the
// solvers: run_scene for the solid and the harmonic level, solve_beam_model
// for the beam.
#pragma once

#include "analyses/converge/converge.hpp"
#include "analyses/converge/level_result.hpp"
#include "scene/model_choice.hpp"

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace coremodal {

// A model level's refinement ladder and how to run one of its levels once.
// The solid ladder is refinement_ladder(), the harmonic's the same with
// kHarmonicExtraLevels more, the beam's beam_refinement_ladder().
struct ModelLadder {
    ModelChoice model;   // solid, beam or harmonic (level_traits: converge_ladder)
    std::string note;    // how the ladder was built, for the report
    std::vector<MeshStep> steps;
    std::function<LevelRun(const MeshStep&)> run_once;  // collective over PETSC_COMM_WORLD
    int n_modes = 0;             // modes asked per run (the solid's is fixed by choose_mode_count)
    int runs_per_level = 0;      // 0: --repeats; the beam: kBeamRunsPerLevel
    double level_budget_s = 0;   // > 0: no further run once a level's runs took this long in all
    int refined_dimensions = 3;  // DOFs ~ k^this (3 for the solid, 2 for the harmonic, 1 for the beam)
    // Roles (kModeRoles) this model cannot have, and why (the beam: ovalling
    // and breathing, which deform the cross-section).
    std::vector<std::pair<std::string, std::string>> unseen_roles;
};

// One run of the solid level on `mesh` with n_modes modes (model = "solid"
// whatever the case says). The peak memory is the process's peak during this
// run (summed over ranks).
LevelRun run_solid_once(const Scene& scene, const MeshSpec& mesh, int n_modes);

// The solid level: refinement_ladder of --unit, or of the default unit fitted
// to --max-dofs. Its run_once reads `n_modes` when it runs (by reference:
// choose_mode_count raises it after the ladder is built), and refers to
// `scene`: both must outlive the ladder.
ModelLadder solid_ladder(const Scene& scene, const ConvergeOptions& o, const int& n_modes);

// The harmonic model level: the solid's unit and levels k = first ... plus
// kHarmonicExtraLevels finer ones (a harmonic run costs ~1 % of the solid's
// on the same section), not bound by --max-dofs (its DOFs are those of one 2D
// problem). Level k meshes exactly the r-z section of the solid's level k.
// A scene that is not axisymmetric is skipped with the reason in `notes`, as
// the beam skips what it cannot solve. `scene` and `n_modes` as for solid_ladder.
std::optional<ModelLadder> harmonic_ladder(const Scene& scene, const ConvergeOptions& o, const int& n_modes,
                                           std::ostream& progress, std::vector<std::string>& notes);

// The beam model level: kBeamLevels levels of the unit beam mesh (h = 1/k,
// k = 1, 2, 4, ...), each run kBeamRunsPerLevel times. The modes asked per
// run start from --modes or the case's and double (up to
// kMaxModesForOvalling) until the coarsest level shows the first torsion and
// axial modes, as the solid's do for ovalling. A scene the beam model cannot
// solve is skipped with its reason in `notes`, not an error. `scene` must
// outlive the ladder.
std::optional<ModelLadder> beam_ladder(const Scene& scene, const ConvergeOptions& o, std::ostream& progress,
                                       std::vector<std::string>& notes);

}  // namespace coremodal
