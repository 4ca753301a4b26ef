// The beam's converge ladder (ModelLevel::converge_ladder): kBeamLevels
// levels of the unit beam mesh (h = 1/k, k = 1, 2, 4, ...), each run
// kBeamRunsPerLevel times. The modes asked per run start from --modes or
// the case's and double (up to kMaxModesForOvalling) until the coarsest
// level shows the first torsion and axial modes, as the solid's do for
// ovalling. A scene the beam model cannot solve is skipped with its reason
// in `notes`, not an error.
#include "beam/beam_model.hpp"
#include "common/format.hpp"
#include "common/stopwatch.hpp"
#include "models/beam/beam_level.hpp"
#include "models/ladder/model_ladder.hpp"
#include "modes/label_tracking.hpp"

#include <algorithm>
#include <stdexcept>

namespace coremodal {
namespace {

// One run of the beam model at refinement k of the unit. Every rank solves
// the same small problem (serial Eigen, no PETSc). Timing: `mesh` is building
// the network, `factor_and_solve` assembly, eigensolve and inertia count (the
// beam assembles problem by problem inside its solve: `assemble` stays 0),
// `classify` the labels, `total` the whole call.
LevelRun run_beam_once(const Scene& scene, const MeshStep& step, int unit_elements, int n_modes) {
    Scene s = scene;
    s.analysis.n_modes = n_modes;
    BeamModelOptions options;
    options.core_elements = unit_elements;
    options.refine = step.k;
    Stopwatch clock;
    const BeamModelResult beam = solve_beam_model(s, options);
    LevelRun run;
    run.timing_s.total = clock.seconds();
    run.timing_s.mesh = beam.timing_s.build;
    run.timing_s.factor_and_solve = beam.timing_s.solve;
    run.timing_s.classify = beam.timing_s.classify;
    run.n_dofs = beam.n_dofs;
    run.complete = beam.verification.complete;
    for (std::size_t i = 0; i < beam.modes.size(); ++i) run.modes.push_back(report_mode(beam.modes[i], int(i) + 1));
    return run;
}

// The modes asked per beam run: as given (--modes, or a band); otherwise
// doubled on the coarsest level until it shows the first torsion and axial
// modes, up to kMaxModesForOvalling. Either way the coarsest level is run
// once, so that a scene the beam cannot solve throws here.
int beam_mode_count(const Scene& scene, const MeshStep& coarsest, const LadderRequest& request) {
    int n_modes = request.n_modes;
    if (request.modes_given) {
        run_beam_once(scene, coarsest, kBeamUnitElements, n_modes);  // can it solve the scene?
        return n_modes;
    }
    for (;;) {
        const LevelRun run = run_beam_once(scene, coarsest, kBeamUnitElements, n_modes);
        if ((has_mode_type(run.modes, "torsion") && has_mode_type(run.modes, "axial")) ||
            n_modes >= kMaxModesForOvalling)
            return n_modes;
        const int more = std::min(2 * n_modes, kMaxModesForOvalling);
        if (request.progress)
            *request.progress << "  beam: no torsion or no axial mode among the first " << n_modes << " modes at "
                              << coarsest.label << ": asking for " << more << std::endl;
        n_modes = more;
    }
}

std::string beam_ladder_note(const Scene& scene) {
    std::string shafts;
    if (scene.supports.kind == SupportKind::chucks) shafts = ", every chuck shaft";
    return "Ladder: level k has k times the elements of the unit beam mesh (" + std::to_string(kBeamUnitElements) +
           " three-node Timoshenko elements along the core, at least two per gap between support edges) in every "
           "such gap" + shafts + ", so h = 1/k exactly (k = 1, 2, 4, ..., ratio 2 between levels). Elements: the "
           "core's / the whole network's. Each level runs " + std::to_string(kBeamRunsPerLevel) +
           " times (about a millisecond each), or as often as fits in " + formatted("%g", kBeamLevelBudget) +
           " s: times are medians. Network = building the beam network; assemble+solve = assembly, eigensolve and "
           "inertia count; labels = labels and effective masses.";
}

}  // namespace

std::optional<ModelLadder> BeamLevel::converge_ladder(const Scene& scene, const LadderRequest& request,
                                                      std::vector<std::string>& notes) {
    ModelLadder ladder;
    ladder.model = ModelChoice::beam;
    ladder.runs_per_level = kBeamRunsPerLevel;
    ladder.level_budget_s = kBeamLevelBudget;
    ladder.refined_dimensions = 1;
    ladder.unseen_roles = {{"ovalling", "a beam's cross-sections are rigid: no ovalling, n >= 2"},
                           {"breathing", "a beam's cross-sections are rigid: no breathing, n = 0 radial"}};
    try {
        ladder.steps = beam_refinement_ladder(scene, kBeamUnitElements, kBeamLevels);
        ladder.n_modes = beam_mode_count(scene, ladder.steps.front(), request);
    } catch (const std::runtime_error& e) {  // InputError, SolveError: the beam cannot solve this scene
        notes.push_back("beam model level skipped: " + std::string(e.what()));
        if (request.progress) *request.progress << "  beam model level skipped: " << e.what() << std::endl;
        return std::nullopt;
    }
    ladder.note = beam_ladder_note(scene);
    ladder.plan = "beam (" + std::to_string(kBeamLevels) + " levels, " + std::to_string(kBeamRunsPerLevel) +
                  " runs per level)";
    ladder.run_once = [&scene](const MeshStep& step, int n_modes) {
        return run_beam_once(scene, step, kBeamUnitElements, n_modes);
    };
    return ladder;
}

}  // namespace coremodal
