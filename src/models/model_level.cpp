#include "models/model_level.hpp"
#include "models/spinning_model.hpp"
#include "models/linearised.hpp"

#include "common/error.hpp"
#include "common/petsc_handle.hpp"
#include "models/choose.hpp"
#include "models/ladder/model_ladder.hpp"
#include "models/response/level_response.hpp"

namespace coremodal {

void warn_about_model(const std::string& source, const std::string& warning, std::vector<std::string>& warnings) {
    if (mpi_rank() == 0) std::cerr << "coremodal: warning: " << source << ": " << warning << std::endl;
    warnings.push_back(warning);
}

Linearised ModelLevel::linearise(const Scene& scene) {
    throw InputError(scene.source_file + ": sensitivities are computed at the beam and the harmonic level; expected "
                     "model = \"harmonic\" (axisymmetric scenes) or \"beam\" (--model)");
}

std::unique_ptr<LevelResponse> ModelLevel::response(const Scene& scene, const BeamModelOptions&) {
    require_response_level(scene);  // says why the scene's level has no response (scene/level_traits.hpp)
    COREMODAL_ASSERT(false);        // a level that spins has its own
    return nullptr;
}

std::unique_ptr<SpinningModel> ModelLevel::spinning(const Scene& scene, const SpinningOptions&) {
    throw cannot_spin(scene, chosen_spinning_level(scene));
}

std::optional<ModelLadder> ModelLevel::converge_ladder(const Scene& scene, const LadderRequest&,
                                                       std::vector<std::string>&) {
    throw InputError(scene.source_file + ": `converge` has no refinement ladder at the " +
                     to_string(chosen_level(scene)) + " level; expected --models solid, harmonic or beam");
}

InputError cannot_spin(const Scene& scene, ModelChoice level) {
    return InputError(scene.source_file + ": [rotation] at model = \"" + to_string(level) +
                      "\"; expected model = \"beam\", \"harmonic\" or \"solid\" (or --model)");
}

void require_one_process_sweep(const Scene& scene, ModelChoice level) {
    if (mpi_size() > 1)
        throw InputError(scene.source_file + ": a Campbell sweep at the " + to_string(level) +
                         " level runs in one process; run it without mpirun");
}

std::vector<double> eigenvalues_of(const std::vector<DistinctMode>& modes, const std::vector<Mode>& all) {
    std::vector<double> out;
    for (const DistinctMode& d : modes) out.push_back(all.at(d.index - 1).eigenvalue);
    return out;
}

}  // namespace coremodal
