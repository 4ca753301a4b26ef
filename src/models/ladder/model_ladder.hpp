// A model level's refinement ladder for `coremodal converge`
// (analyses/converge): what ModelLevel::converge_ladder hands out — the
// meshes the level runs (refinement_ladder.hpp), how it runs one of them
// once, and what the report says about the ladder. The solid's in
// models/solid/solid_ladder.cpp, the harmonic level's in
// models/harmonic/harmonic_ladder.cpp, the beam's in
// models/beam/beam_ladder.cpp; analyses/converge measures the runs (time,
// processor time, the solver's events, peak memory), repeats them and
// analyses the levels, and never names a level.
#pragma once

#include "models/ladder/refinement_ladder.hpp"
#include "modes/mode_set.hpp"
#include "results/run_report.hpp"
#include "scene/model_choice.hpp"

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace coremodal {

// Where factor_and_solve goes, from PETSc's and SLEPc's event logs (seconds,
// rank 0): numeric and symbolic factorizations (the shift-and-invert
// Cholesky and the LDL^T of the inertia count), triangular solves, and the
// M-orthogonalization of the Krylov basis. The rest of factor_and_solve is
// the other Krylov-Schur work (M products, projected problem) and the
// residual and orthonormality checks. (Events are inclusive: the products of
// the shift-and-invert operator contain the solves, so they are not listed.)
struct SolverBreakdown {
    double factor_s = 0, solve_s = 0, orthogonalize_s = 0;
};

// Most modes asked per run while looking for the first ovalling mode (the
// meshed levels) or the first torsion and axial modes (the beam).
inline constexpr int kMaxModesForOvalling = 64;

// What one run of one mesh level gives back (model-level independent). The
// level fills n_dofs, timing_s, modes and complete; the driver measures the
// rest around the run.
struct LevelRun {
    long n_dofs = 0;
    Timing timing_s;
    SolverBreakdown solver_s;
    double cpu_s = 0;  // processor time of the run (user + system, this process, rank 0):
                       // on a shared machine less disturbed by other processes than wall time
    double peak_memory_mb = 0;
    std::vector<Mode> modes;  // frequency order; shapes not kept
    bool complete = true;     // the solver proved no mode missing
};

// What a level needs to build its ladder: converge's options and, for the
// meshed levels, the run of a scene (analyses/run's run_scene, quiet and
// writing nothing: given by the driver, which is above models/).
struct LadderRequest {
    std::optional<std::string> unit;  // "W/P/A/Z" (--unit); default: default_unit(scene) fitted to max_dofs
    int first = 1, levels = 4;        // k = first ... first + levels - 1 (the solid's)
    long max_dofs = 0;                // bound on the solid's finest level; 0: none
    int n_modes = 0;                  // modes per run asked (--modes, or the case's)
    bool modes_given = false;         // --modes or a band: the beam does not raise its count
    std::string repeats_words;        // "3 runs per level, ..." (--repeats), for the meshed levels' plan
    std::function<RunReport(Scene)> run_scene;
    std::ostream* progress = nullptr;  // progress lines (rank 0), none when null
};

// A model level's refinement ladder and how to run one of its levels once.
struct ModelLadder {
    ModelChoice model;   // the level (level_traits: converge_ladder)
    std::string plan;    // "solid (4 levels, ...)", for the announcement
    std::string note;    // how the ladder was built, for the report
    std::vector<MeshStep> steps;
    // One run of a step with n modes asked; collective over PETSC_COMM_WORLD.
    std::function<LevelRun(const MeshStep&, int n_modes)> run_once;
    int n_modes = 0;             // modes asked per run (the meshed levels': converge's choose_mode_count)
    int runs_per_level = 0;      // 0: --repeats; the beam: kBeamRunsPerLevel
    double level_budget_s = 0;   // > 0: no further run once a level's runs took this long in all
    int refined_dimensions = 3;  // DOFs ~ k^this (3 for the solid, 2 for the harmonic, 1 for the beam)
    // Roles (kModeRoles) this model cannot have, and why (the beam: ovalling
    // and breathing, which deform the cross-section).
    std::vector<std::pair<std::string, std::string>> unseen_roles;
};

// The unit of the solid ladder (and of the harmonic ladder, which shares its
// levels): --unit as given, or the default unit fitted to max_dofs at the
// solid's levels. `budget_note` says what the bound changed.
UnitMesh meshed_unit(const Scene& scene, const LadderRequest& request, std::string& budget_note);

// "1/1/8/21 (...; along per axial segment 2+2+13+2+2)": the unit of a ladder as its steps multiply it.
std::string unit_text(const Scene& scene, const UnitMesh& unit, const MeshStep& first);

// One run of a meshed level (`model`: solid or harmonic) on `mesh` with
// n_modes modes, by request.run_scene: the run's modes, DOFs, timings and
// completeness (the mode shapes dropped).
LevelRun run_meshed_once(const LadderRequest& request, const Scene& scene, ModelChoice model, const MeshSpec& mesh,
                         int n_modes);

}  // namespace coremodal
