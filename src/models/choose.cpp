#include "models/choose.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "models/beam/beam_level.hpp"
#include "models/coupled/coupled_level.hpp"
#include "models/harmonic/harmonic_level.hpp"
#include "models/solid/solid_level.hpp"

namespace coremodal {

std::optional<std::string> one_sided_contact_reason(const Scene& scene) {
    for (const ChuckSpec& chuck : scene.supports.chucks)
        if (chuck.interface.kind == InterfaceKind::spring && chuck.interface.contact == ContactKind::one_sided)
            return "the " + chuck.name + " chuck is not expanded: its contact closes under gravity on one side "
                   "of the bore only (contact = \"one-sided\")";
    return std::nullopt;
}

std::optional<std::string> why_not_axisymmetric(const Scene& scene) {
    if (scene.mesh.file)
        return "a [mesh] file: the harmonic level meshes the scene's own r-z section";
    if (const auto why = one_sided_contact_reason(scene)) return why;
    for (const ChuckSpec& chuck : scene.supports.chucks)
        for (const ExpandingElement& e : chuck.expanding)
            if (e.segments > 0)
                return "the " + chuck.name + " chuck's expanding element at " + significant(e.center * 1e3) +
                       " mm has " + std::to_string(e.segments) + " segments, which are not axisymmetric";
    if (scene.web) return "the paper web ([web]) pulls on one line of the roll's surface, which is not axisymmetric";
    return std::nullopt;
}

std::optional<std::string> why_coupled(const Scene& scene) {
    if (scene.mesh.file) return std::nullopt;
    std::optional<std::string> why;
    std::vector<std::string> varies;  // what varies around
    for (const ChuckSpec& chuck : scene.supports.chucks)
        for (const ExpandingElement& e : chuck.expanding) {
            if (e.segments == 0 || chuck.interface.contact == ContactKind::one_sided) continue;
            if (chuck.interface.kind != InterfaceKind::spring) return std::nullopt;  // ties over arcs: the solid
            if (!why) why = why_not_axisymmetric(scene);
            if (varies.empty()) varies.push_back("the pads' spring layer");
        }
    const auto add = [&](const std::string& reason, const std::string& what) {
        why = why ? *why + "; " + reason : reason;
        varies.push_back(what);
    };
    if (const auto contact = one_sided_contact_reason(scene)) add(*contact, "the contact's arc");
    if (scene.web) add("the paper web pulls on one line of the roll's surface", "the web's line");
    if (!why) return std::nullopt;
    std::string list;
    for (const std::string& v : varies) list += (list.empty() ? "" : v == varies.back() ? " and " : ", ") + v;
    return *why + "; the roll and chucks are bodies of revolution and only " + list +
           " varies around, so the coupled harmonics solve it exactly in theta at 2D cost";
}

void require_axisymmetric(const Scene& scene) {
    if (const auto why = one_sided_contact_reason(scene))
        throw InputError(scene.source_file + ": model = \"harmonic\": " + *why +
                         "; expected model = \"solid\" or \"auto\", or contact = \"uniform\" for the uniform "
                         "soft layer of earlier versions");
    if (const auto why = why_not_axisymmetric(scene))
        throw InputError(scene.source_file + ": model = \"harmonic\": " + *why +
                         "; expected full bands and no [mesh] file, or model = \"solid\"");
}

ModelChoice chosen_level(const Scene& scene) {
    const ModelChoice asked = scene.model;
    if (asked != ModelChoice::automatic) return asked;
    if (!why_not_axisymmetric(scene)) return ModelChoice::harmonic;
    return why_coupled(scene) ? ModelChoice::coupled : ModelChoice::solid;
}

ModelChoice chosen_spinning_level(const Scene& scene) {
    const ModelChoice level = chosen_level(scene);
    if (scene.model == ModelChoice::automatic && !level_traits(level).spins)
        return ModelChoice::solid;
    return level;
}

std::string level_choice_text(const Scene& scene, const std::string& given) {
    const ModelChoice asked = scene.model;
    if (asked == ModelChoice::beam) return "beam (" + given + "): a Timoshenko beam network; [mesh] is not used";
    if (asked == ModelChoice::harmonic)
        return "harmonic (" + given + "): the r-z section, one 2D eigenproblem per circumferential wave number n";
    if (asked == ModelChoice::coupled)
        return "coupled (" + given + "): the r-z section, harmonics n = 0 ... N coupled by segmented expanding "
               "elements, the paper web or a one-sided contact in one 2D-cost eigenproblem per independent set";
    const std::optional<std::string> not_axisymmetric = why_not_axisymmetric(scene);
    if (asked == ModelChoice::automatic && not_axisymmetric)
        if (const auto coupled = why_coupled(scene)) return "coupled (" + given + "; " + *coupled + ")";
    if (asked == ModelChoice::automatic)
        return not_axisymmetric ? "solid (" + given + "; not a body of revolution: " + *not_axisymmetric + ")"
                                : "harmonic (" + given + "; a body of revolution: no segmented expanding element, "
                                                         "no [mesh] file)";
    return "solid (" + given + "): quadratic hexahedra" +
           (not_axisymmetric ? std::string()
                             : "; the scene is a body of revolution, so model = \"auto\" or \"harmonic\" would solve "
                               "it on its r-z section, much faster");
}

std::unique_ptr<ModelLevel> make_model_level(const Scene& scene) { return make_model_level(chosen_level(scene)); }

std::unique_ptr<ModelLevel> make_model_level(ModelChoice level) {
    switch (level) {
        case ModelChoice::beam: return std::make_unique<BeamLevel>();
        case ModelChoice::harmonic: return std::make_unique<HarmonicLevel>();
        case ModelChoice::coupled: return std::make_unique<CoupledLevel>();
        case ModelChoice::solid:
        case ModelChoice::automatic: break;  // chosen_level resolves "auto"
    }
    return std::make_unique<SolidLevel>();
}

}  // namespace coremodal
