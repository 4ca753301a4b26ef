#include "models/solve_steps.hpp"

#include "beam/eigenvalue_scale.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

SolveRequest solve_request(const Scene& scene) {
    SolveRequest request;
    static_cast<ModeRequest&>(request) = mode_request(scene, ModeFamilies::beam_and_section);
    request.max_iterations = scene.analysis.max_iterations;
    return request;
}

std::string shift_scale_text(const Scene& scene) {
    const EigenvalueEstimate scale = elastic_eigenvalue_scale(scene, ModeFamilies::beam_and_section);
    return "      shift from the scale of the first elastic mode: " + scale.family + " estimate, " +
           significant(std::sqrt(scale.lambda) / (2 * M_PI)) + " Hz";
}

SolvedModes solve_for_case(const Scene& scene, const OperatorSet& operators, const SolveRequest& request,
                           const Progress& progress, const std::string& problem) {
    try {
        return solve_modes(operators, request, progress);
    } catch (const InputError& e) {
        throw InputError(scene.source_file + ": " + problem + e.what());
    }
}

Mode numbered_mode(int index, double lambda, double relative_residual) {
    Mode mode;
    mode.index = index;
    mode.eigenvalue = lambda;
    mode.frequency_hz = std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI);
    mode.relative_residual = relative_residual;
    return mode;
}

BodyHeld body_held(const Scene& scene) {
    return scene.supports.kind == SupportKind::free && !scene.web ? BodyHeld::free : BodyHeld::held;
}

}  // namespace coremodal
