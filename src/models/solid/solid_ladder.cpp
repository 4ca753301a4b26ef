// The solid's converge ladder (ModelLevel::converge_ladder): uniform
// h-refinement of the unit mesh by k = first, ..., the reference every other
// ladder is measured against.
#include "models/ladder/model_ladder.hpp"
#include "models/solid/solid_level.hpp"

namespace coremodal {

std::optional<ModelLadder> SolidLevel::converge_ladder(const Scene& scene, const LadderRequest& request,
                                                       std::vector<std::string>&) {
    std::string budget_note;
    const UnitMesh unit = meshed_unit(scene, request, budget_note);
    ModelLadder ladder;
    ladder.model = ModelChoice::solid;
    ladder.steps = refinement_ladder(scene, unit, request.first, request.levels);
    const long finest = estimate_dofs(scene, ladder.steps.back().mesh);
    if (request.unit && request.max_dofs > 0 && finest > request.max_dofs)
        budget_note = "the finest level (estimated " + std::to_string(finest) + " DOFs) exceeds --max-dofs " +
                      std::to_string(request.max_dofs) + "; --unit was taken as given";
    ladder.note = "Ladder: level k has k times the elements of the unit mesh " +
                  unit_text(scene, unit, ladder.steps.front()) + " in every direction and in every axial segment, so h = 1/k "
                  "exactly (ratios (k+1)/k between levels; graded segments keep their size ratio). Hexahedra " +
                  scene.mesh.element + (budget_note.empty() ? "." : "; " + budget_note + ".");
    ladder.plan = "solid (" + std::to_string(request.levels) + " levels, " + request.repeats_words + ")";
    ladder.run_once = [&scene, request](const MeshStep& step, int n_modes) {
        return run_meshed_once(request, scene, ModelChoice::solid, step.mesh, n_modes);
    };
    return ladder;
}

}  // namespace coremodal
