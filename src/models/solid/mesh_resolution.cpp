#include "models/solid/mesh_resolution.hpp"

#include "common/format.hpp"
#include "modes/tracking.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/mesh_rule.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

bool is_elastic_family(const ModeLabel& label) {
    return label.type != "rigid" && label.type != "support" && label.type != "mixed";
}

bool same_family(const ModeLabel& a, const ModeLabel& b) { return a.type == b.type && a.n == b.n && a.m == b.m; }

// How far above a harmonic mode a solid mode may lie and still be matched to
// it from above: the solid's cells put the wall on quadratic arcs, not on the
// circle, which can leave a mode a few 1e-6 below the exact one.
constexpr double kBelowTolerance = 1e-3;

// The harmonic counterpart of a solid mode: of the same label, the highest at
// or below it. A solid mesh is too stiff, not too soft, around, so its mode
// lies above its counterpart; the nearest in frequency could be the next
// mode of the same label above (a 0.5 m ring at 16 around: its n = 2 ovalling
// pair at 74.1 Hz is 45 % above the harmonic level's 51.0 Hz, and nearer the
// next n = 2, m = 0 mode at 92.3 Hz). None below: the nearest.
const Mode* counterpart(const Mode& s, const std::vector<Mode>& harmonic) {
    const Mode* below = nullptr;
    const Mode* nearest = nullptr;
    for (const Mode& h : harmonic) {
        if (!same_family(s.label, h.label) || h.frequency_hz <= 0) continue;
        if (h.frequency_hz <= s.frequency_hz * (1 + kBelowTolerance) &&
            (!below || h.frequency_hz > below->frequency_hz))
            below = &h;
        if (!nearest || std::abs(h.frequency_hz - s.frequency_hz) < std::abs(nearest->frequency_hz - s.frequency_hz))
            nearest = &h;
    }
    return below ? below : nearest;
}

}  // namespace

MeshResolution compare_with_harmonic(const std::vector<Mode>& solid, const std::vector<Mode>& harmonic) {
    MeshResolution worst;
    for (const Mode& s : solid) {
        if (!is_elastic_family(s.label) || s.frequency_hz <= 0) continue;
        const Mode* match = counterpart(s, harmonic);
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
        // The level's count as a run at it would have it: raised for a thin wall or the band.
        const int around = std::max(elements_around(level, scene.core.inner_diameter, scene.core.outer_diameter),
                                    mesh_rule(scene, level_target_error(level)).around);
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
                       " off (docs/validation/accuracy-by-level.md)";
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
