#include "geometry/tube_section.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// Two quadratic elements resolve the strain gradient across a clamp zone edge
// well enough; one would make the zone a single rigid slab of nodes.
constexpr int kMinElementsPerSegment = 2;
// Breakpoints closer than this (relative to the length) are merged, so that a
// clamp zone starting at the core end does not create a sliver segment.
constexpr double kBreakpointMergeTolerance = 1e-9;

std::vector<double> axial_breakpoints(const Scene& scene) {
    const double L = scene.core.length;
    std::vector<double> z = {0.0, L};
    for (const auto& clamp : scene.supports.clamps) {
        z.push_back(clamp.z_start);
        z.push_back(clamp.z_end);
    }
    std::sort(z.begin(), z.end());
    std::vector<double> unique;
    for (double v : z)
        if (unique.empty() || v - unique.back() > kBreakpointMergeTolerance * L) unique.push_back(v);
    unique.back() = L;
    return unique;
}

// Distributes n_total elements over the segments in proportion to length
// (largest remainders first), with a floor of kMinElementsPerSegment.
std::vector<int> distribute_elements(const std::vector<double>& lengths, int n_total) {
    double total = 0;
    for (double l : lengths) total += l;
    std::vector<int> counts(lengths.size());
    for (size_t i = 0; i < lengths.size(); ++i)
        counts[i] = std::max(kMinElementsPerSegment,
                             static_cast<int>(std::round(n_total * lengths[i] / total)));
    return counts;
}

bool inside_a_clamp(const Scene& scene, double z0, double z1) {
    for (const auto& c : scene.supports.clamps)
        if (z0 >= c.z_start - kBreakpointMergeTolerance && z1 <= c.z_end + kBreakpointMergeTolerance) return true;
    return false;
}

bool is_clamp_edge(const Scene& scene, double z) {
    const double tol = kBreakpointMergeTolerance * scene.core.length;
    if (z < tol || z > scene.core.length - tol) return false;  // a core end is free, not a clamp edge
    for (const auto& c : scene.supports.clamps)
        if (std::abs(z - c.z_start) < tol || std::abs(z - c.z_end) < tol) return true;
    return false;
}

// Free-core segments are refined towards the clamp edges they touch.
AxialGrading grading(const Scene& scene, double z0, double z1) {
    if (inside_a_clamp(scene, z0, z1)) return AxialGrading::uniform;
    const bool at_start = is_clamp_edge(scene, z0), at_end = is_clamp_edge(scene, z1);
    if (at_start && at_end) return AxialGrading::toward_both;
    if (at_start) return AxialGrading::toward_start;
    if (at_end) return AxialGrading::toward_end;
    return AxialGrading::uniform;
}

}  // namespace

TubeSection make_tube_section(const Scene& scene) {
    TubeSection section;
    const double ri = scene.core.inner_diameter / 2, ro = scene.core.outer_diameter / 2;
    section.layers.push_back({"core", ri, ro, scene.mesh.n_wall});
    if (scene.rest_paper)
        section.layers.push_back(
            {"rest_paper", ro, scene.rest_paper->outer_diameter / 2, scene.mesh.n_rest_paper});

    const auto z = axial_breakpoints(scene);
    std::vector<double> lengths;
    for (size_t i = 0; i + 1 < z.size(); ++i) lengths.push_back(z[i + 1] - z[i]);
    auto counts = distribute_elements(lengths, scene.mesh.n_along);
    if (!scene.mesh.along_per_segment.empty()) {
        COREMODAL_ASSERT(scene.mesh.along_per_segment.size() == counts.size());
        counts = scene.mesh.along_per_segment;
    }
    for (size_t i = 0; i + 1 < z.size(); ++i)
        section.segments.push_back({z[i], z[i + 1], counts[i], grading(scene, z[i], z[i + 1])});

    COREMODAL_ASSERT(scene.mesh.n_around % 4 == 0 && scene.mesh.n_around >= 8);
    section.n_around = scene.mesh.n_around;
    return section;
}

}  // namespace coremodal
