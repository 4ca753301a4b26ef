// [analysis] (modes, band) and [mesh] (level, overrides, a user .msh file)
// (scene/case_reader.hpp).
#include "scene/case_reader.hpp"

#include "common/error.hpp"
#include "scene/mesh_rule.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace coremodal::case_reading {

namespace fs = std::filesystem;

AnalysisSpec CaseReader::read_analysis(const Section& top) const {
    AnalysisSpec spec;
    const std::optional<Section> analysis = section(top, "analysis", "analysis");
    if (!analysis) return spec;
    at_most_one(*analysis, "modes", "band");
    spec.n_modes = integer(*analysis, "modes").value_or(spec.n_modes);
    if (const toml::node* band = get(*analysis, "band")) read_band(*analysis, *band, spec);
    spec.tolerance = quantity(*analysis, "tolerance").value_or(spec.tolerance);
    spec.max_iterations = integer(*analysis, "max_iterations").value_or(spec.max_iterations);
    return spec;
}

void CaseReader::read_band(const Section& s, const toml::node& node, AnalysisSpec& spec) const {
    const toml::array& band = *node.as_array();
    const std::string what = echo(s, "band", node);
    if (band.size() != 2)
        fail(node, what + ": expected two frequencies, e.g. band = [\"0 Hz\", \"500 Hz\"]");
    const double lo = to_si(band[0], Dimension::frequency, what);
    const double hi = to_si(band[1], Dimension::frequency, what);
    if (lo < 0) fail(band[0], what + ": the lower frequency must be zero or positive");
    if (!(hi > lo))
        fail(band[1], what + ": the upper frequency must be larger than the lower one");
    spec.f_min_hz = lo;
    spec.f_max_hz = hi;
}

MeshSpec CaseReader::read_mesh(const Section& top, const Scene& scene) const {
    MeshSpec spec;
    const std::optional<Section> mesh = section(top, "mesh", "mesh");
    if (mesh) spec.element = choice(*mesh, "element", kElementTypes).value_or(spec.element);
    if (mesh && get(*mesh, "file")) {
        spec.file = read_mesh_file(*mesh);
        return spec;
    }
    const MeshLevel& level = mesh_level(mesh);
    spec.level = level.name;
    spec.n_wall = level.n_wall;
    spec.n_rest_paper = level.n_rest_paper;
    // The level's counts, raised where the band needs more (scene/mesh_rule.hpp).
    const MeshRule rule = mesh_rule(scene, level_target_error(level));
    spec.n_around =
        std::max(elements_around(level, scene.core.inner_diameter, scene.core.outer_diameter), rule.around);
    if (mesh) apply_mesh_overrides(*mesh, spec);
    if (!mesh || !get(*mesh, "along")) {
        const std::optional<int> along = elements_along(
            scene.core.length, scene.core.outer_diameter, spec.n_around, level.axial_aspect);
        if (!along)
            fail(mesh ? mesh->table->source() : top.table->source(),
                 "[mesh] level = \"" + spec.level + "\" would need more than " +
                     std::to_string(kMaxElementsAlong) + " elements along [core] length = " +
                     format_quantity(scene.core.length, Dimension::length) +
                     "; expected a shorter core, or give [mesh] along");
        spec.n_along = std::max(*along, rule.along);
    }
    return spec;
}

const MeshLevel& CaseReader::mesh_level(const std::optional<Section>& mesh) const {
    const std::string name =
        mesh ? choice(*mesh, "level", mesh_level_names()).value_or("default") : "default";
    return *find_mesh_level(name);
}

void CaseReader::apply_mesh_overrides(const Section& mesh, MeshSpec& spec) const {
    const auto override_with = [&](std::string_view key, int& target) {
        if (const std::optional<int> v = integer(mesh, key)) {
            target = *v;
            spec.level = "custom";
        }
    };
    override_with("through_wall", spec.n_wall);
    override_with("through_rest_paper", spec.n_rest_paper);
    override_with("around", spec.n_around);
    override_with("along", spec.n_along);
    if (spec.n_around % kAroundMultiple != 0)
        fail(*get(mesh, "around"),
             echo(mesh, "around", *get(mesh, "around")) +
                 " must be a multiple of 4; expected e.g. 16, 32, 48 or 64");
}

std::string CaseReader::read_mesh_file(const Section& mesh) const {
    for (std::string_view key :
         {"level", "through_wall", "through_rest_paper", "around", "along"})
        if (const toml::node* node = get(mesh, key))
            fail(*node, echo(mesh, key, *node) +
                            " has no effect with [mesh] file; expected "
                            "either a mesh file or mesh settings, not both");
    const toml::node& node = *get(mesh, "file");
    const fs::path given(std::string(*node.value<std::string_view>()));
    const fs::path resolved =
        given.is_absolute() ? given : fs::path(path_).parent_path() / given;
    const std::string what = echo(mesh, "file", node) + ": ";
    if (given.extension() != ".msh")
        fail(node, what + "expected a gmsh mesh file ending in .msh");
    std::error_code ec;
    if (!fs::is_regular_file(resolved, ec))
        fail(node, what + "no mesh file '" + resolved.string() +
                       "'; expected a path relative to the case file's folder");
    if (!std::ifstream(resolved).good())
        fail(node, what + "cannot read mesh file '" + resolved.string() + "' (" +
                       std::strerror(errno) + ")");
    return resolved.string();
}

}  // namespace coremodal::case_reading
