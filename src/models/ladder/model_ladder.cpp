#include "models/ladder/model_ladder.hpp"

namespace coremodal {

UnitMesh meshed_unit(const Scene& scene, const LadderRequest& request, std::string& budget_note) {
    budget_note.clear();
    if (request.unit) return parse_unit(*request.unit, "--unit");  // the user's unit is taken as given
    return fit_unit_to_budget(scene, default_unit(scene), request.first, request.levels, request.max_dofs, budget_note);
}

std::string unit_text(const Scene& scene, const UnitMesh& unit, const MeshStep& first) {
    std::string segments;
    for (int n : first.mesh.along_per_segment) {
        if (!segments.empty()) segments += "+";
        segments += std::to_string(n / first.k);
    }
    const std::string paper = scene.rest_paper ? std::to_string(unit.n_rest_paper) : std::string("-");
    return std::to_string(unit.n_wall) + "/" + paper + "/" + std::to_string(unit.n_around) + "/" +
           std::to_string(first.mesh.n_along / first.k) + " (through the wall / through the rest paper / around / "
           "along; along per axial segment " + segments + ")";
}

// For the harmonic level (the same r-z section as the solid's level; n_around
// only sets the revolved mesh the modes are shown and named on) n_dofs is
// the largest one-harmonic problem's, and the timings sum over the harmonics.
LevelRun run_meshed_once(const LadderRequest& request, const Scene& scene, ModelChoice model, const MeshSpec& mesh,
                         int n_modes) {
    Scene s = scene;
    s.model = model;  // the case may name another level for its runs; this ladder is `model`'s
    s.mesh = mesh;
    s.analysis.n_modes = n_modes;
    RunReport report = request.run_scene(std::move(s));
    LevelRun run;
    run.n_dofs = report.model.n_dofs;
    run.timing_s = report.timing_s;
    run.complete = report.modes.verification.complete;
    run.modes = std::move(report.modes.modes);
    for (Mode& m : run.modes) std::vector<double>().swap(m.shape);
    return run;
}

}  // namespace coremodal
