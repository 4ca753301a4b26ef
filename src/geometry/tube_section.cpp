#include "geometry/tube_section.hpp"

#include "common/error.hpp"
#include "effects/chuck_placement.hpp"

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

// Axial zones where the core is held: rigid clamp zones, or the expanding
// elements of elastic chucks (global z). Their edges are where the wall's
// strain concentrates (docs/validation/models.md, "Example cases"), so the mesh grades towards them.
std::vector<std::pair<double, double>> held_zones(const Scene& scene) {
    std::vector<std::pair<double, double>> zones;
    for (const auto& c : scene.supports.clamps) zones.push_back({c.z_start, c.z_end});
    for (const auto& chuck : scene.supports.chucks) {
        const ChuckPlacement place = chuck_placement(scene, chuck);
        for (const auto& e : chuck.expanding) zones.push_back(place.element_range(e).pair());
    }
    return zones;
}

std::vector<double> axial_breakpoints(const Scene& scene) {
    const double L = scene.core.length;
    std::vector<double> z = {0.0, L};
    for (const auto& [a, b] : held_zones(scene)) {
        z.push_back(a);
        z.push_back(b);
    }
    for (const auto& chuck : scene.supports.chucks)
        z.push_back(chuck.name == "right" ? L - chuck.inserted_length : chuck.inserted_length);
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
    const double tol = kBreakpointMergeTolerance * scene.core.length;
    for (const auto& [a, b] : held_zones(scene))
        if (z0 >= a - tol && z1 <= b + tol) return true;
    return false;
}

bool is_clamp_edge(const Scene& scene, double z) {
    const double tol = kBreakpointMergeTolerance * scene.core.length;
    if (z < tol || z > scene.core.length - tol) return false;  // a core end is free, not a clamp edge
    for (const auto& [a, b] : held_zones(scene))
        if (std::abs(z - a) < tol || std::abs(z - b) < tol) return true;
    return false;
}

// Radial over circumferential size allowed in a chuck disc's rings. Steel
// 100-1000 times stiffer than the paper deforms smoothly: its section stays
// nearly plane, so one quadratic element across each ring carries it. On
// case 07 this halves the rings' cells (224 -> 128 a layer) and moves f1 by
// 0.04 % (docs/theory/chucks.md).
constexpr double kChuckRingAspect = 3.0;

// Elements along a shaft: five times as long as the elements are wide around
// the shaft (about the shaft's radius at 32 around; finer levels refine it
// with the circumference, so a refinement ladder refines the shaft too). The
// shaft carries only end loads and its own inertia, so its bending moment
// varies almost linearly and a few quadratic elements resolve it: on case 07
// the earlier two widths (13 elements on the 250 mm shaft) gave the same f1
// to 0.01 % (bench/results/log.md).
constexpr double kShaftElementAspect = 5.0;

int shaft_elements(double length, double radius, int n_around) {
    const double size = kShaftElementAspect * 2 * M_PI * radius / n_around;
    return std::max(kMinElementsPerSegment, static_cast<int>(std::ceil(length / size - 1e-9)));
}

void add_chucks(const Scene& scene, TubeSection& section) {
    const double L = scene.core.length;
    for (const auto& c : scene.supports.chucks) {
        ChuckBody body;
        body.name = c.name;
        body.body_radius = c.body_diameter / 2;
        body.shaft_radius = c.shaft_diameter / 2;
        body.shaft_below = c.name != "right";
        body.z_body_start = body.shaft_below ? 0.0 : L - c.inserted_length;
        body.z_body_end = body.shaft_below ? c.inserted_length : L;
        body.shaft_length = c.shaft_length;
        body.n_shaft = shaft_elements(c.shaft_length, body.shaft_radius, scene.mesh.n_around);
        section.chucks.push_back(body);
        const ChuckPlacement place = chuck_placement(scene, c);
        // A chuck not expanded (one-sided contact) may touch the bore anywhere
        // on its body: the retracted elements sit at or below its surface.
        if (c.interface.kind == InterfaceKind::spring && c.interface.contact == ContactKind::one_sided)
            section.interfaces.push_back({c.name, place.body_range().pair()});
        else
            for (const auto& e : c.expanding) section.interfaces.push_back({c.name, place.element_range(e).pair()});
    }
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

// Size ratio of the largest to the smallest element of a segment graded
// towards clamp edges. Measured on case 02 (3 through the wall, 32 around;
// f1 with 24 / 48 / 96 elements along): uniform 62.018 / 61.687 / 61.479 Hz,
// ratio 4: 61.649 / 61.493 / 61.391 Hz, ratio 8: 61.545 / 61.455 / 61.377 Hz,
// ratio 16: 61.489 / 61.439 Hz. The clamp edge is singular, so every mesh
// converges slowly; grading by 8 gives with 24 elements what uniform gives
// with ~80, and keeps the middle elements short enough for higher modes.
constexpr double kClampEdgeGradingRatio = 8.0;

// n element sizes growing geometrically by `ratio` end to end, from small to large.
std::vector<double> geometric_sizes(int n, double ratio) {
    std::vector<double> sizes(n);
    const double step = n > 1 ? std::pow(ratio, 1.0 / (n - 1)) : 1.0;
    for (int i = 0; i < n; ++i) sizes[i] = std::pow(step, i);
    return sizes;
}

}  // namespace

std::vector<double> segment_layer_fractions(const AxialSegment& seg) {
    std::vector<double> sizes;
    const int n = seg.n_elements;
    switch (seg.grading) {
    case AxialGrading::uniform: sizes.assign(n, 1.0); break;
    case AxialGrading::toward_start: sizes = geometric_sizes(n, kClampEdgeGradingRatio); break;
    case AxialGrading::toward_end:
        sizes = geometric_sizes(n, kClampEdgeGradingRatio);
        std::reverse(sizes.begin(), sizes.end());
        break;
    case AxialGrading::toward_both: {
        // Small at both ends, largest in the middle: two mirrored halves,
        // each graded by the full ratio (as gmsh's "Bump" 1/8 did before the
        // extruded rebuild; grading each half by only sqrt(8) cost case 02's
        // default mesh 0.07 % in f1: 61.4823 against 61.4397 Hz).
        const int half = (n + 1) / 2;
        sizes = geometric_sizes(half, kClampEdgeGradingRatio);
        std::vector<double> back(sizes.rbegin() + (n % 2), sizes.rend());
        sizes.insert(sizes.end(), back.begin(), back.end());
        break;
    }
    }
    double total = 0;
    for (double s : sizes) total += s;
    std::vector<double> fractions;
    double sum = 0;
    for (double s : sizes) fractions.push_back((sum += s) / total);
    fractions.back() = 1.0;
    return fractions;
}

int chuck_ring_elements(double r0, double r1, int n_around) {
    const double around = 2 * M_PI * r1 / n_around;
    return std::max(1, static_cast<int>(std::ceil((r1 - r0) / (kChuckRingAspect * around) - 1e-9)));
}

long count_chuck_hex20_nodes(const TubeSection& s) {
    // A hex20 layer of a 2D quad mesh with V vertices and E edges has V + E
    // nodes on its faces and V at its middle (the vertical edges' midpoints).
    const long t = s.n_around, q = t / 4;
    long nodes = 0;
    for (const ChuckBody& c : s.chucks) {
        const long n_shaft_ring = chuck_ring_elements(kOGridCoreShare * c.shaft_radius, c.shaft_radius, s.n_around);
        const long n_body_ring = c.body_radius > c.shaft_radius + 1e-9
                                     ? chuck_ring_elements(c.shaft_radius, c.body_radius, s.n_around)
                                     : 0;
        const long v_shaft = (q + 1) * (q + 1) + n_shaft_ring * t, e_shaft = 2 * q * (q + 1) + 2 * n_shaft_ring * t;
        const long v_body = v_shaft + n_body_ring * t, e_body = e_shaft + 2 * n_body_ring * t;
        long z_body = 0;
        for (const AxialSegment& seg : s.segments)
            if (seg.z_start >= c.z_body_start - 1e-9 && seg.z_end <= c.z_body_end + 1e-9) z_body += seg.n_elements;
        nodes += (z_body + 1) * (v_body + e_body) + z_body * v_body;
        nodes += c.n_shaft * (v_shaft + e_shaft) + c.n_shaft * v_shaft;  // its face at the body is the body's
    }
    return nodes;
}

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

    add_chucks(scene, section);
    COREMODAL_ASSERT(scene.mesh.n_around % 4 == 0 && scene.mesh.n_around >= 8);
    section.n_around = scene.mesh.n_around;
    return section;
}

}  // namespace coremodal
