#include "models/solid/mesh_resolution.hpp"

#include "common/format.hpp"
#include "modes/tracking.hpp"
#include "scene/mesh_levels.hpp"

#include <cmath>

namespace coremodal {
namespace {

bool is_elastic_family(const ModeLabel& label) {
    return label.type != "rigid" && label.type != "support" && label.type != "mixed";
}

bool same_family(const ModeLabel& a, const ModeLabel& b) { return a.type == b.type && a.n == b.n && a.m == b.m; }

}  // namespace

MeshResolution compare_with_harmonic(const std::vector<Mode>& solid, const std::vector<Mode>& harmonic) {
    MeshResolution worst;
    for (const Mode& s : solid) {
        if (!is_elastic_family(s.label) || s.frequency_hz <= 0) continue;
        const Mode* match = nullptr;
        for (const Mode& h : harmonic)
            if (same_family(s.label, h.label) && h.frequency_hz > 0 &&
                (!match || std::abs(h.frequency_hz - s.frequency_hz) < std::abs(match->frequency_hz - s.frequency_hz)))
                match = &h;
        if (!match) continue;
        ++worst.compared;
        const double error = s.frequency_hz / match->frequency_hz - 1;
        if (worst.compared == 1 || std::abs(error) > std::abs(worst.error())) {
            const int compared = worst.compared;
            worst = {compared, s.index, label_text(s.label), s.frequency_hz, match->frequency_hz};
        }
    }
    return worst;
}

std::optional<std::string> level_that_resolves(const MeshResolution& r, const Scene& scene) {
    const int n_around = scene.mesh.n_around;
    for (const MeshLevel& level : kMeshLevels) {
        const int around = elements_around(level, scene.core.inner_diameter, scene.core.outer_diameter);
        if (around <= n_around) continue;
        const double predicted = std::abs(r.error()) * std::pow(double(n_around) / around, kAroundConvergenceOrder);
        if (predicted < kMeshWarnError) return std::string(level.name);
    }
    return std::nullopt;
}

std::optional<std::string> mesh_resolution_text(const MeshResolution& r, const Scene& scene) {
    const MeshSpec& mesh = scene.mesh;
    const double error = std::abs(r.error());
    if (r.compared == 0 || error <= kMeshWarnError) return std::nullopt;
    const std::string percent = significant(100 * r.error(), 3) + " %";
    std::string text = "the mesh (" + mesh.level + ", " + std::to_string(mesh.n_around) +
                       " elements around) does not resolve mode " + std::to_string(r.mode_index) + " (" + r.label +
                       "): " + significant(r.solid_hz, 5) + " Hz here against " + significant(r.harmonic_hz, 5) +
                       " Hz at the harmonic level (same section, exact around), " + percent +
                       " off (docs/accuracy-vs-cost.md)";
    if (const auto level = level_that_resolves(r, scene)) {
        text += "; expected --mesh " + *level + " or finer";
    } else {
        // The n_around the (n_around)^-p law needs, rounded up to a multiple of 4.
        const double needed = mesh.n_around * std::pow(error / kMeshWarnError, 1 / kAroundConvergenceOrder);
        text += "; expected at least " + std::to_string(4 * static_cast<int>(std::ceil(needed / 4))) +
                " elements around ([mesh] n_around), or model = \"harmonic\"";
    }
    return text;
}

}  // namespace coremodal
