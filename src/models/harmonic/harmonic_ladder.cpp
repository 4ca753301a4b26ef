// The harmonic level's converge ladder (ModelLevel::converge_ladder): the
// solid's unit and levels k = first ... plus kHarmonicExtraLevels finer
// ones (a harmonic run costs ~1 % of the solid's on the same section), not
// bound by --max-dofs (its DOFs are those of one 2D problem). Level k
// meshes exactly the r-z section of the solid's level k. A scene that is not
// axisymmetric is skipped with the reason in `notes`, as the beam skips what
// it cannot solve.
#include "models/choose.hpp"
#include "models/harmonic/harmonic_level.hpp"
#include "models/ladder/model_ladder.hpp"

namespace coremodal {

std::optional<ModelLadder> HarmonicLevel::converge_ladder(const Scene& scene, const LadderRequest& request,
                                                          std::vector<std::string>& notes) {
    if (const auto why = why_not_axisymmetric(scene)) {
        const std::string note = "harmonic model level skipped: " + *why;
        notes.push_back(note);
        if (request.progress) *request.progress << "  " << note << std::endl;
        return std::nullopt;
    }
    std::string budget_note;
    const UnitMesh unit = meshed_unit(scene, request, budget_note);
    ModelLadder ladder;
    ladder.model = ModelChoice::harmonic;
    ladder.refined_dimensions = 2;
    ladder.steps = refinement_ladder(scene, unit, request.first, request.levels + kHarmonicExtraLevels);
    ladder.note = "Ladder (r–z section only; exact in theta): level k meshes the r–z section of the solid's level k "
                  "(unit " + unit_text(scene, unit, ladder.steps.front()) + ", h = 1/k) in quad8 cells and solves one "
                  "eigenproblem per circumferential wave number n, so it has no circumferential discretization; it "
                  "runs the solid's levels and " + std::to_string(kHarmonicExtraLevels) + " finer ones (k up to " +
                  std::to_string(ladder.steps.back().k) + "), not bound by --max-dofs. Around only sets the revolved "
                  "mesh the modes are named on. DOFs: the largest one-harmonic problem; assemble and factor+solve "
                  "sum over the harmonics (with their inertia counts)" +
                  (budget_note.empty() ? "." : "; the unit is the solid's: " + budget_note + ".");
    ladder.plan = "harmonic (" + std::to_string(request.levels + kHarmonicExtraLevels) + " levels, r-z section only)";
    ladder.run_once = [&scene, request](const MeshStep& step, int n_modes) {
        return run_meshed_once(request, scene, ModelChoice::harmonic, step.mesh, n_modes);
    };
    return ladder;
}

}  // namespace coremodal
