// [web]: the paper web leaving the roll (scene/scene.hpp WebSpec,
// scene/web_springs.hpp, effects/web.hpp, docs/theory/web.md). Every key but shear_modulus is required;
// its default is Baum's rule. What the model makes of the web goes into the
// scene's assumptions, which every level echoes.
#include "scene/case_reader.hpp"

#include "scene/web_springs.hpp"

namespace coremodal::case_reading {

std::optional<WebSpec> CaseReader::read_web(const Section& top, Scene& scene) const {
    const std::optional<Section> web = section(top, "web", "web");
    if (!web) return std::nullopt;
    WebSpec spec;
    spec.tension = required(*web, "tension", "the web's tension per unit width, e.g. tension = \"300 N/m\"");
    spec.span = required(*web, "span", "the free span to the first guide roller, e.g. span = \"1.2 m\"");
    spec.angle = required(*web, "angle", "the direction the web leaves in, e.g. angle = \"30 deg\" (0 = +x)");
    spec.thickness = required(*web, "thickness", "the web's thickness, e.g. thickness = \"80 um\"");
    spec.modulus = required(*web, "modulus", "the web's in-plane modulus along its length, e.g. modulus = \"5 GPa\"");
    // The web's stiffest spring is its stretch along the web, E t / s per
    // unit length of the roll (docs/theory/web.md): a span so short that it is
    // beyond rigid is refused (a web into a nip is a support, not a span).
    const double shortest = spec.modulus * spec.thickness / beyond_rigid(scene.core, Dimension::line_force);
    if (spec.span < shortest)
        fail(*get(*web, "span"),
             echo(*web, "span", *get(*web, "span")) + " makes the web's stretch E t / s = " +
                 format_quantity(spec.modulus * spec.thickness / spec.span, Dimension::pressure) +
                 " per unit length of the roll (N/m^2) beyond rigid: more than 1e12 times " +
                 beyond_rigid_reason(scene.core, Dimension::line_force) +
                 ", so it holds the roll as a rigid line would (to 1e-12); expected a span of at least " +
                 format_quantity(shortest, Dimension::length) + " (a web into a nip is a support, not a span)");
    if (const std::optional<double> g = quantity(*web, "shear_modulus")) {
        spec.shear_modulus = *g;
        spec.shear_source = "[web] shear_modulus";
    } else {
        spec.shear_modulus = default_web_shear_modulus(spec.modulus);
        spec.shear_source = kWebShearRule;
    }
    for (std::string& line : web_assumptions(spec)) scene.assumptions.push_back(std::move(line));
    return spec;
}

}  // namespace coremodal::case_reading
