#include "analyses/converge/converge_study.hpp"

#include <cmath>

namespace coremodal {

const ModelStudy* find_reference(const std::vector<ModelStudy>& models) {
    for (const auto& m : models)
        if (m.traits.reference) return &m;
    return nullptr;
}

namespace {

ModelError model_error(const std::string& model, const std::string& role, const TrackedMode& own,
                       const TrackedMode& solid) {
    const Richardson &ra = *own.richardson, &rb = *solid.richardson;
    ModelError e;
    e.model = model;
    e.role = role;
    e.id = own.key.text();
    e.solid_id = solid.key.text();
    e.f0_hz = ra.f0;
    e.solid_f0_hz = rb.f0;
    e.relative = (ra.f0 - rb.f0) / rb.f0;
    e.known_to = (ra.error_estimate + ra.f0_uncertainty.value_or(0.0)) / std::abs(ra.f0) +
                 (rb.error_estimate + rb.f0_uncertainty.value_or(0.0)) / std::abs(rb.f0);
    return e;
}

}  // namespace

std::vector<ModelError> model_errors(const std::vector<ModelStudy>& models) {
    std::vector<ModelError> out;
    const ModelStudy* solid = find_reference(models);
    if (!solid) return out;
    for (const auto& m : models) {
        if (m.traits.reference) continue;
        for (const auto& [role, type] : kModeRoles) {
            const TrackedMode* a = find_role(m, role);
            const TrackedMode* b = find_role(*solid, role);
            if (a && b && a->richardson && b->richardson) out.push_back(model_error(m.model, role, *a, *b));
        }
    }
    return out;
}

std::vector<std::optional<double>> error_against_solid(const TrackedMode& mode, const std::vector<ModelStudy>& models) {
    const ModelStudy* solid = find_reference(models);
    const TrackedMode* reference = solid && !mode.role.empty() ? find_role(*solid, mode.role) : nullptr;
    if (!reference || !reference->richardson) return {};
    const double f0 = reference->richardson->f0;
    std::vector<std::optional<double>> out;
    for (const auto& f : mode.frequency_hz)
        out.push_back(f ? std::optional<double>(std::abs(*f - f0) / std::abs(f0)) : std::nullopt);
    return out;
}

}  // namespace coremodal
