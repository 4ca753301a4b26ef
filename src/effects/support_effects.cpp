#include "effects/support_effects.hpp"

#include "effects/web.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

Eigen::Matrix3d SpringLayer::per_area(double theta) const {
    const Eigen::Vector3d er(std::cos(theta), std::sin(theta), 0);
    return tangential * Eigen::Matrix3d::Identity() + (normal - tangential) * er * er.transpose();
}

double contact_area(const ExpandingElement& e, double bore_radius) {
    const double angle = e.segments > 0 ? e.segments * e.segment_angle : 2 * M_PI;
    return angle * bore_radius * e.width;
}

double SpringLayer::sideways_stiffness(const ExpandingElement& e, double bore_radius) const {
    return (normal + tangential) / 2 * contact_area(e, bore_radius);
}

double SpringLayer::axial_stiffness(const ExpandingElement& e, double bore_radius) const {
    return tangential * contact_area(e, bore_radius);
}

namespace {

ChuckEffects chuck_effects(const Scene& scene, const ChuckSpec& chuck) {
    ChuckEffects out;
    out.placement = chuck_placement(scene, chuck);
    const ChuckInterface& f = chuck.interface;
    out.bonded = f.kind == InterfaceKind::bonded;
    if (!out.bonded && f.contact == ContactKind::one_sided)
        out.one_sided = OneSidedContact{(scene.core.inner_diameter - chuck.body_diameter) / 2,
                                        StackContact{f.normal_stiffness, contact_law().residual_pressure},
                                        f.tangential_stiffness / f.normal_stiffness};
    else if (!out.bonded)
        out.spring_layer = SpringLayer{f.normal_stiffness, f.tangential_stiffness};
    const BearingSpec& b = chuck.bearing;
    if (b.rigid) return out;
    out.bearing_springs = BearingSprings{b.radial_stiffness, b.tilting_stiffness};
    if (b.frame_mass) out.frame = FrameMass{*b.frame_mass, b.frame_stiffness.value_or(0.0), out.placement.bearing_z()};
    return out;
}

}  // namespace

SupportEffects support_effects(const Scene& scene) {
    SupportEffects out;
    for (const ClampSpec& c : scene.supports.clamps) out.clamps.push_back({c.name, {c.z_start, c.z_end}});
    for (const ChuckSpec& chuck : scene.supports.chucks) out.chucks.push_back(chuck_effects(scene, chuck));
    for (const ChuckEffects& c : out.chucks)
        if (c.one_sided) out.gravity = GravityPreload{};
    return out;
}

std::vector<std::string> effect_names(const Scene& scene, const SupportEffects& effects) {
    std::vector<std::string> out{"core"};
    if (scene.rest_paper) out.push_back("rest_paper");
    if (!effects.clamps.empty()) out.push_back(RigidClamp::kName);
    if (scene.web) out.push_back(PaperWeb::kName);
    const auto& chucks = effects.chucks;
    if (chucks.empty()) return out;
    const auto any = [&](auto pred) { return std::any_of(chucks.begin(), chucks.end(), pred); };
    out.push_back(ChuckEffects::kName);
    if (any([](const ChuckEffects& c) { return c.spring_layer.has_value(); })) out.push_back(SpringLayer::kName);
    if (any([](const ChuckEffects& c) { return c.one_sided.has_value(); })) out.push_back(OneSidedContact::kName);
    if (effects.gravity) out.push_back(GravityPreload::kName);
    if (any([](const ChuckEffects& c) { return c.bearing_springs.has_value(); })) out.push_back(BearingSprings::kName);
    if (any([](const ChuckEffects& c) { return c.frame.has_value(); })) out.push_back(FrameMass::kName);
    return out;
}

// Declared in scene/scene.hpp; defined here so that the summary's list is
// built from the very effect structs the model levels apply.
std::vector<std::string> Scene::effects() const { return effect_names(*this, support_effects(*this)); }

}  // namespace coremodal
