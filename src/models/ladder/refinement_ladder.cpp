#include "models/ladder/refinement_ladder.hpp"

#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "geometry/tube_section.hpp"
#include "scene/mesh_levels.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace coremodal {

std::string mesh_counts_text(const MeshSpec& m, bool rest_paper) {
    return std::to_string(m.n_wall) + "/" + (rest_paper ? std::to_string(m.n_rest_paper) : std::string("-")) +
           "/" + std::to_string(m.n_around) + "/" + std::to_string(m.n_along);
}

UnitMesh default_unit(const Scene& scene) {
    UnitMesh unit;
    const double along = std::ceil(double(scene.mesh.n_along) * kUnitElementsAround / scene.mesh.n_around);
    unit.n_along = std::max(kMinElementsAlong, static_cast<int>(along));
    return unit;
}

UnitMesh parse_unit(const std::string& text, const std::string& option) {
    const std::string expected = "; expected WALL/PAPER/AROUND/ALONG element counts of the k = 1 level, e.g. 1/1/8/21";
    std::vector<int> v;
    std::stringstream s(text);
    std::string item;
    while (std::getline(s, item, '/')) {
        std::size_t used = 0;
        int value = 0;
        try {
            value = std::stoi(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || value < 1)
            throw InputError(option + " " + text + ": '" + item + "' is not a positive whole number" + expected);
        v.push_back(value);
    }
    if (v.size() != 4) throw InputError(option + " " + text + ": " + std::to_string(v.size()) + " counts" + expected);
    if (v[2] % 4 != 0)
        throw InputError(option + " " + text + ": around = " + std::to_string(v[2]) +
                         " must be a multiple of 4 (8 keeps ovalling pairs degenerate)" + expected);
    return {v[0], v[1], v[2], v[3]};
}

long estimate_dofs(const MeshSpec& m, bool rest_paper) {
    const long r = m.n_wall + (rest_paper ? m.n_rest_paper : 0), t = m.n_around, z = m.n_along;
    if (m.element == "hex27") return 3 * (2 * r + 1) * (2 * t) * (2 * z + 1);
    // Corner nodes, then mid-edge nodes on radial, circumferential and axial edges.
    const long nodes = t * ((r + 1) * (z + 1) + r * (z + 1) + (r + 1) * (z + 1) + (r + 1) * z);
    return 3 * nodes;
}

long estimate_dofs(const Scene& scene, const MeshSpec& mesh) {
    Scene meshed = scene;
    meshed.mesh = mesh;
    const TubeSection section = make_tube_section(meshed);
    MeshSpec tube = mesh;
    tube.n_along = 0;
    for (const AxialSegment& seg : section.segments) tube.n_along += seg.n_elements;
    // Chucks are meshed with hex20 (docs/theory/chucks.md).
    return estimate_dofs(tube, scene.rest_paper.has_value()) + 3 * count_chuck_hex20_nodes(section);
}

UnitMesh fit_unit_to_budget(const Scene& scene, UnitMesh unit, int first, int levels, long max_dofs,
                            std::string& note) {
    note.clear();
    if (max_dofs <= 0 || scene.mesh.file) return unit;
    auto finest_dofs = [&](const UnitMesh& u) {
        return estimate_dofs(scene, refinement_ladder(scene, u, first, levels).back().mesh);
    };
    const int asked = unit.n_along;
    while (finest_dofs(unit) > max_dofs && unit.n_along > kMinUnitElementsAlong) --unit.n_along;
    if (unit.n_along != asked)
        note = "the unit's elements along were lowered from " + std::to_string(asked) + " to " +
               std::to_string(unit.n_along) + " so that the finest level stays within --max-dofs " +
               std::to_string(max_dofs) + " (estimated " + std::to_string(finest_dofs(unit)) + " DOFs)";
    if (finest_dofs(unit) > max_dofs)
        note += std::string(note.empty() ? "" : "; ") + "the finest level (estimated " +
                std::to_string(finest_dofs(unit)) + " DOFs) exceeds --max-dofs " + std::to_string(max_dofs) +
                " even with the fewest elements along; use fewer --levels or a smaller --unit";
    return unit;
}

namespace {

void check_levels(int levels) {
    if (levels < 3) throw InputError("--levels " + std::to_string(levels) + ": Richardson extrapolation needs at least 3");
}

// Elements of each axial segment (clamp zones, graded free spans) of the
// unit mesh, as the mesher would cut them.
std::vector<int> unit_segments(const Scene& scene, const UnitMesh& unit) {
    Scene unit_scene = scene;
    unit_scene.mesh.n_wall = unit.n_wall;
    unit_scene.mesh.n_rest_paper = unit.n_rest_paper;
    unit_scene.mesh.n_around = unit.n_around;
    unit_scene.mesh.n_along = unit.n_along;
    unit_scene.mesh.along_per_segment.clear();
    std::vector<int> segments;
    for (const AxialSegment& segment : make_tube_section(unit_scene).segments) segments.push_back(segment.n_elements);
    return segments;
}

}  // namespace

std::vector<MeshStep> refinement_ladder(const Scene& scene, const UnitMesh& unit, int first, int levels) {
    if (scene.mesh.file)
        throw InputError(scene.source_file + ": [mesh] file = " + *scene.mesh.file +
                         ": converge refines the generated mesh; expected a case without a mesh file");
    if (first < 1) throw InputError("--first " + std::to_string(first) + ": expected a multiple k >= 1");
    check_levels(levels);
    // Every level multiplies each of the unit's segment counts by k.
    const std::vector<int> segments = unit_segments(scene, unit);
    std::vector<MeshStep> steps;
    for (int k = first; k < first + levels; ++k) {
        MeshStep step;
        step.k = k;
        step.h = 1.0 / k;
        step.mesh = scene.mesh;
        step.mesh.level = "converge k=" + std::to_string(k);
        step.mesh.n_wall = k * unit.n_wall;
        step.mesh.n_rest_paper = k * unit.n_rest_paper;
        step.mesh.n_around = k * unit.n_around;
        step.mesh.along_per_segment.clear();
        for (int n : segments) step.mesh.along_per_segment.push_back(k * n);
        step.mesh.n_along = std::accumulate(step.mesh.along_per_segment.begin(), step.mesh.along_per_segment.end(), 0);
        step.counts = mesh_counts_text(step.mesh, scene.rest_paper.has_value());
        step.label = "k=" + std::to_string(k) + " " + step.counts;
        steps.push_back(std::move(step));
    }
    return steps;
}

std::vector<MeshStep> beam_refinement_ladder(const Scene& scene, int unit_elements, int levels) {
    if (unit_elements < 1) throw InputError("beam unit: " + std::to_string(unit_elements) + " elements: expected at least 1");
    check_levels(levels);
    std::vector<MeshStep> steps;
    for (int i = 0, k = 1; i < levels; ++i, k *= 2) {
        BeamModelOptions options;
        options.core_elements = unit_elements;
        options.refine = k;
        const BeamNetwork net = build_beam_network(scene, options);
        MeshStep step;
        step.k = k;
        step.h = 1.0 / k;
        step.mesh = scene.mesh;  // unused by the beam
        step.counts = std::to_string(net.beams.front().nodes.size() / 2) + "/" + std::to_string(net.n_elements());
        step.label = "k=" + std::to_string(k) + " " + step.counts;
        steps.push_back(std::move(step));
    }
    return steps;
}

}  // namespace coremodal
