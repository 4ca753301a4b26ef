// Eigenvalue sensitivities (sensitivity.hpp): the level's modes at p, then per
// parameter its operators at p(1 ± h) on the same DOFs (models/linearised.hpp).
#include "analyses/sensitivity/sensitivity.hpp"

#include "models/choose.hpp"
#include "models/linearised.hpp"
#include "common/error.hpp"
#include "scene/free_span.hpp"
#include "scene/materials_library.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

namespace coremodal {
namespace {

// The free–free roll over the free span: its 6 rigid modes and the first bending pair.
constexpr int kFreeSpanModes = 8;

}  // namespace

ModelChoice sensitivity_level(const Scene& scene) {
    const ModelChoice level = chosen_level(scene);
    if (!level_traits(level).sensitivities)
        throw InputError(scene.source_file + ": model = \"" + to_string(level) + "\": sensitivities are computed at the beam and "
                         "the harmonic level; expected model = \"harmonic\" (axisymmetric scenes) or \"beam\" "
                         "(--model)");
    return level;
}

namespace {

// The scene's level linearises it (models/linearised.hpp); sensitivity_level
// refuses a level without sensitivities first, with the case's words.
Linearised linearised(const Scene& scene) {
    sensitivity_level(scene);
    return make_model_level(scene)->linearise(scene);
}

// d ln f / d ln p of every distinct mode, for every parameter.
struct Derivatives {
    Linearised base;
    std::vector<std::vector<double>> dlnf;  // [mode][parameter]
    std::vector<std::string> methods;
};

double frequency_of(const std::vector<DistinctMode>& modes, const ModeKey& key) {
    for (const DistinctMode& d : modes)
        if (d.key == key) return d.frequency_hz;
    throw SolveError("sensitivities: the mode " + key.text() + " is missing at a perturbed parameter value (its "
                     "label changed); expected a smaller step");
}

template <typename SceneOf>
Derivatives derivatives(const CaseParameters& c, const std::vector<double>& values, double h, SceneOf scene_of) {
    Derivatives d;
    d.base = linearised(scene_of(c.scene(values)));
    d.dlnf.assign(d.base.modes.size(), std::vector<double>(values.size(), 0.0));
    for (size_t j = 0; j < values.size(); ++j) {
        std::vector<double> plus = values, minus = values;
        plus[j] *= 1 + h;
        minus[j] *= 1 - h;
        const Scene sp = scene_of(c.scene(plus)), sm = scene_of(c.scene(minus));
        const double dlnp = std::log(plus[j] / minus[j]);
        if (const auto dl = d.base.delta_lambda(sp, sm)) {
            d.methods.push_back("operators");
            for (size_t i = 0; i < d.base.modes.size(); ++i)
                d.dlnf[i][j] = (*dl)[i] / (2 * d.base.eigenvalues[i] * dlnp);
            continue;
        }
        d.methods.push_back("re-solved");
        const Linearised lp = linearised(sp), lm = linearised(sm);
        for (size_t i = 0; i < d.base.modes.size(); ++i)
            d.dlnf[i][j] = std::log(frequency_of(lp.modes, d.base.modes[i].key) /
                                    frequency_of(lm.modes, d.base.modes[i].key)) / dlnp;
    }
    return d;
}

std::vector<ModeSensitivity> mode_sensitivities(const Derivatives& d) {
    std::vector<ModeSensitivity> out;
    for (size_t i = 0; i < d.base.modes.size(); ++i)
        out.push_back({d.base.modes[i].key, d.base.modes[i].frequency_hz, d.dlnf[i]});
    return out;
}

const ModeSensitivity* first_bending(const std::vector<ModeSensitivity>& modes) {
    for (const ModeSensitivity& m : modes)
        if (m.key.type == "bending") return &m;
    return nullptr;
}

}  // namespace

std::vector<std::string> material_and_contact_keys(const Scene& scene) {
    std::vector<std::string> keys;
    const auto material = [&](const std::string& owner, const OrthotropicMaterial& m) {
        const auto& names = m.is_isotropic() ? isotropic_material_keys() : orthotropic_material_keys();
        for (std::string_view k : names) keys.push_back(owner + ".material." + std::string(k));
    };
    material("core", scene.core.material);
    if (scene.rest_paper) material("rest_paper", scene.rest_paper->material);
    if (scene.supports.kind == SupportKind::chucks) {
        const ChuckSpec& left = scene.supports.chucks.at(0);
        if (left.interface.kind == InterfaceKind::spring)
            for (const char* k : {"normal_stiffness", "tangential_stiffness"}) keys.push_back("supports.left." + std::string(k));
        for (const char* k : {"E", "density"}) keys.push_back("supports.left.material." + std::string(k));
    }
    return keys;
}

const ModeSensitivity* SensitivityResult::find(const ModeKey& key) const {
    for (const ModeSensitivity& m : modes)
        if (m.key == key) return &m;
    return nullptr;
}

SensitivityResult eigen_sensitivities(const CaseParameters& c, const std::vector<double>& values,
                                      const SensitivityOptions& options) {
    SensitivityResult r;
    r.parameters = c.parameters();
    r.values = values;
    const Scene scene = c.scene(values);
    r.level = sensitivity_level(scene);
    const auto same = [](Scene s) { return s; };
    const Derivatives d = derivatives(c, values, options.step, same);
    r.methods = d.methods;
    r.modes = mode_sensitivities(d);
    const ModeSensitivity* f1 = first_bending(r.modes);
    if (!options.chuck_factor || scene.supports.kind != SupportKind::chucks || !f1) return r;
    const Derivatives free = derivatives(c, values, options.step, [](const Scene& scene) {
        // Unlike the run's, the free roll keeps the scene's mesh counts: the
        // derivative differences operators on one fixed set of DOFs.
        return free_span_scene(scene, kFreeSpanModes);
    });
    const std::vector<ModeSensitivity> free_modes = mode_sensitivities(free);
    const ModeSensitivity* f2 = first_bending(free_modes);
    if (!f2) return r;
    r.f2 = *f2;
    r.k = f1->frequency_hz / f2->frequency_hz;
    for (size_t j = 0; j < values.size(); ++j) r.dlnk_dlnp.push_back(f1->dlnf_dlnp[j] - f2->dlnf_dlnp[j]);
    return r;
}

}  // namespace coremodal
