#include "scene/scene_description.hpp"

#include "common/format.hpp"
#include "scene/chuck_contact.hpp"
#include "scene/level_traits.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/mesh_rule.hpp"
#include "scene/model_choice.hpp"

#include "scene/toml_text.hpp"
#include "scene/units.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace coremodal {
namespace {

// Every path of a table: its keys, their sub-tables' keys, and the items of
// arrays of tables numbered from 1.
void collect_paths(const toml::node& node, const std::string& path, std::set<std::string>& out) {
    if (!path.empty()) out.insert(path);
    const std::string prefix = path.empty() ? "" : path + ".";
    if (const toml::table* table = node.as_table()) {
        for (const auto& [key, value] : *table) collect_paths(value, prefix + std::string(key.str()), out);
    } else if (const toml::array* array = node.as_array(); array && array->is_array_of_tables()) {
        for (std::size_t i = 0; i < array->size(); ++i) collect_paths((*array)[i], prefix + std::to_string(i + 1), out);
    }
}

std::string length(double v) { return format_quantity(v, Dimension::length); }

// A TOML string as written: "text".
std::string toml_quoted(std::string_view text) {
    std::string out(1, '"');
    out.append(text);
    out += '"';
    return out;
}

struct Row {
    std::string name;  // "[core] inner_diameter"
    std::string value;
    std::string origin;
};

// Rows of the resolved scene, table by table, each with its origin.
class SceneRows {
public:
    SceneRows(const Scene& scene, const KeySources& sources) : scene_(scene), sources_(sources) {
        top();
        core();
        rest_paper();
        supports();
        analysis();
        mesh();
    }

    std::string text() const {
        // Origins in one column; a long text (a description) just runs past it.
        constexpr std::size_t kMaxColumn = 64;
        std::size_t width = 0;
        for (const Row& r : rows_)
            if (const std::size_t w = r.name.size() + 3 + r.value.size(); w <= kMaxColumn) width = std::max(width, w);
        std::string out;
        for (const Row& r : rows_) {
            std::string line = "  " + r.name + " = " + r.value;
            line.resize(std::max(line.size(), width + 2), ' ');
            out += line + "   " + r.origin + "\n";
        }
        return out;
    }

private:
    const Scene& scene_;
    const KeySources& sources_;
    std::vector<Row> rows_;
    // A right support the file does not give mirrors the left one: every
    // origin under it says so instead.
    bool mirrored_ = false;

    void add(std::string name, std::string value, std::string origin) {
        rows_.push_back({std::move(name), std::move(value), std::move(origin)});
    }

    // "file" when the file gives `path`, "command line" when an option set it, else `otherwise`.
    std::string origin(const std::string& path, std::string otherwise = "default") const {
        if (sources_.on_command_line.contains(path)) return "command line";
        if (mirrored_) return "mirrors [supports.left]";
        if (sources_.in_file_has(path)) return "file";
        return otherwise;
    }

    void top() {
        add("name", toml_quoted(scene_.name), origin("name", "default: the file name"));
        if (!scene_.description.empty()) add("description", toml_quoted(scene_.description), "file");
        add("model", toml_quoted(to_string(scene_.model)), origin("model"));
    }

    void core() {
        const CoreSpec& c = scene_.core;
        add("[core] inner_diameter", length(c.inner_diameter), origin("core.inner_diameter"));
        add("[core] outer_diameter", length(c.outer_diameter),
            sources_.in_file_has("core.wall")
                ? "from wall = " + length((c.outer_diameter - c.inner_diameter) / 2)
                : origin("core.outer_diameter"));
        add("[core] length", length(c.length), origin("core.length"));
        material("[core]", "core.material", c.material);
    }

    void rest_paper() {
        if (!scene_.rest_paper) {
            add("[rest_paper]", "none (a bare core)", "default");
            return;
        }
        const double thickness = (scene_.rest_paper->outer_diameter - scene_.core.outer_diameter) / 2;
        add("[rest_paper] outer_diameter", length(scene_.rest_paper->outer_diameter),
            sources_.in_file_has("rest_paper.thickness") ? "from thickness = " + length(thickness)
                                                          : origin("rest_paper.outer_diameter"));
        material("[rest_paper]", "rest_paper.material", scene_.rest_paper->material);
    }

    // The material's name, then each of its values: from the file, or from
    // the library entry it is based on (material.source names it).
    void material(const std::string& owner, const std::string& path, const OrthotropicMaterial& m) {
        add(owner + " material", toml_quoted(m.name), origin(path, "default"));
        const std::string library = m.source.substr(0, m.source.find(','));
        const std::string display = owner.substr(0, owner.size() - 1) + ".material] ";
        const auto value = [&](std::string_view key, double v, Dimension d) {
            add(display + std::string(key), format_quantity(v, d), origin(path + "." + std::string(key), library));
        };
        if (m.is_isotropic()) {
            value("E", m.E_z, Dimension::pressure);
            value("nu", m.nu_rz, Dimension::dimensionless);
        } else {
            value("E_r", m.E_r, Dimension::pressure);
            value("E_theta", m.E_theta, Dimension::pressure);
            value("E_z", m.E_z, Dimension::pressure);
            value("G_rtheta", m.G_rtheta, Dimension::pressure);
            value("G_rz", m.G_rz, Dimension::pressure);
            value("G_thetaz", m.G_thetaz, Dimension::pressure);
            value("nu_rtheta", m.nu_rtheta, Dimension::dimensionless);
            value("nu_rz", m.nu_rz, Dimension::dimensionless);
            value("nu_thetaz", m.nu_thetaz, Dimension::dimensionless);
        }
        value("density", m.density, Dimension::density);
    }

    void supports() {
        const SupportSpec& s = scene_.supports;
        const char* type = s.kind == SupportKind::free ? "free" : s.kind == SupportKind::clamped ? "clamped" : "chucks";
        add("[supports] type", toml_quoted(type),
            origin("supports.type", sources_.in_file_has("supports") ? "default" : "default: no [supports], free-free"));
        for (const ClampSpec& clamp : s.clamps) this->clamp(clamp);
        for (const ChuckSpec& chuck : s.chucks) this->chuck(chuck);
        mirrored_ = false;
    }

    void clamp(const ClampSpec& c) {
        const std::string path = "supports." + c.name;
        const std::string display = "[supports." + c.name + "] ";
        mirrored_ = c.name == "right" && !sources_.in_file_has(path);
        add(display + "length", length(c.z_end - c.z_start), origin(path + ".length"));
        const std::string placed = sources_.in_file_has(path + ".center")  ? origin(path + ".center") + " (center)"
                                   : sources_.in_file_has(path + ".start") ? origin(path + ".start") + " (start)"
                                                                           : origin(path + ".start", "default: at the core end");
        add(display + "zone", "z = " + length(c.z_start) + " to " + length(c.z_end) + " from the left core end", placed);
    }

    void chuck(const ChuckSpec& c) {
        const std::string path = "supports." + c.name;
        const std::string display = "[supports." + c.name + "] ";
        mirrored_ = c.name == "right" && !sources_.in_file_has(path);
        const double bore = scene_.core.inner_diameter;
        add(display + "inserted_length", length(c.inserted_length), origin(path + ".inserted_length"));
        const std::string clearance = length((bore - c.body_diameter) / 2);
        add(display + "body_diameter", length(c.body_diameter),
            sources_.in_file_has(path + ".body_diameter")
                ? origin(path + ".body_diameter")
                : origin(path + ".clearance", "default") + ": bore - 2 x clearance " + clearance);
        add(display + "shaft_diameter", length(c.shaft_diameter),
            origin(path + ".shaft_diameter", "default: the body diameter"));
        add(display + "shaft_length", length(c.shaft_length), origin(path + ".shaft_length"));
        material(display.substr(0, display.size() - 1), path + ".material", c.material);
        for (std::size_t i = 0; i < c.expanding.size(); ++i) expanding(c, i, path);
        interface(c, path, display);
        bearing(c.bearing, path, display);
    }

    void expanding(const ChuckSpec& c, std::size_t i, const std::string& chuck_path) {
        const ExpandingElement& e = c.expanding[i];
        const std::string path = chuck_path + ".expanding." + std::to_string(i + 1);
        const std::string display = "[supports." + c.name + ".expanding #" + std::to_string(i + 1) + "] ";
        add(display + "center", length(e.center), origin(path + ".center"));
        add(display + "width", length(e.width), origin(path + ".width"));
        if (e.segments > 0)
            add(display + "segments", std::to_string(e.segments) + " of " +
                                          format_quantity(e.segment_angle * 180 / std::numbers::pi, Dimension::dimensionless) + " deg",
                origin(path + ".segments"));
        else
            add(display + "segments", "none (a full band)", origin(path + ".segments"));
    }

    void interface(const ChuckSpec& c, const std::string& path, const std::string& display) {
        const ChuckInterface& f = c.interface;
        add(display + "interface", f.kind == InterfaceKind::bonded ? "\"bonded\"" : "\"spring\"",
            origin(path + ".interface"));
        if (f.kind == InterfaceKind::bonded) return;
        add(display + "expanded", f.expanded ? "true" : "false", origin(path + ".expanded"));
        if (f.contact == ContactKind::one_sided)
            add(display + "contact", "\"one-sided\"", origin(path + ".contact", "default when not expanded"));
        std::string normal = origin(path + ".normal_stiffness");
        if (!sources_.in_file_has(path + ".normal_stiffness") && !mirrored_)
            normal = f.expansion_pressure ? "from expansion_pressure = " +
                                                format_quantity(*f.expansion_pressure, Dimension::pressure) + " (" +
                                                origin(path + ".expansion_pressure") + ")"
                                          : f.contact == ContactKind::one_sided
                                              ? "at zero contact pressure; rises with the static pressure (not expanded)"
                                              : "from the residual contact pressure (not expanded)";
        add(display + "normal_stiffness", format_quantity(f.normal_stiffness, Dimension::stiffness_per_area), normal);
        add(display + "tangential_stiffness", format_quantity(f.tangential_stiffness, Dimension::stiffness_per_area),
            origin(path + ".tangential_stiffness", "default: Mindlin's ratio x normal_stiffness"));
    }

    void bearing(const BearingSpec& b, const std::string& chuck_path, const std::string& chuck_display) {
        const std::string path = chuck_path + ".bearing";
        const std::string display = chuck_display.substr(0, chuck_display.size() - 2) + ".bearing] ";
        add(display + "type", b.rigid ? "\"rigid\"" : "\"elastic\"",
            origin(path + ".type", !sources_.in_file_has(path) ? "default: no [bearing]"
                                   : b.rigid                     ? "default"
                                                                 : "default: elastic, as stiffnesses are given"));
        if (b.rigid) return;
        add(display + "radial_stiffness", format_quantity(b.radial_stiffness, Dimension::stiffness),
            origin(path + ".radial_stiffness"));
        add(display + "tilting_stiffness", format_quantity(b.tilting_stiffness, Dimension::rotational_stiffness),
            origin(path + ".tilting_stiffness"));
        if (b.frame_mass && b.frame_stiffness) {
            add(display + "frame_mass", format_quantity(*b.frame_mass, Dimension::mass), origin(path + ".frame_mass"));
            add(display + "frame_stiffness", format_quantity(*b.frame_stiffness, Dimension::stiffness),
                origin(path + ".frame_stiffness"));
        } else {
            add(display + "frame_mass", "none (springs to the ground)", "default");
        }
    }

    void analysis() {
        const AnalysisSpec& a = scene_.analysis;
        if (a.f_max_hz) {
            add("[analysis] band", format_quantity(a.f_min_hz.value_or(0), Dimension::frequency) + " to " +
                                       format_quantity(*a.f_max_hz, Dimension::frequency),
                origin("analysis.band"));
        } else {
            add("[analysis] modes", std::to_string(a.n_modes), origin("analysis.modes"));
        }
        add("[analysis] tolerance", format_quantity(a.tolerance, Dimension::dimensionless), origin("analysis.tolerance"));
        add("[analysis] max_iterations", std::to_string(a.max_iterations) + (scene_.model != ModelChoice::automatic && !level_traits(scene_.model).meshed ? " (not used by the beam level)" : ""),
            origin("analysis.max_iterations"));
    }

    void mesh() {
        const MeshSpec& m = scene_.mesh;
        if (m.file) {
            add("[mesh] file", toml_quoted(*m.file), origin("mesh.file"));
        } else {
            const std::string level = m.level == "custom" ? "from the counts given" : origin("mesh.level");
            add("[mesh] level", toml_quoted(m.level), level);
            const std::string from_level = sources_.on_command_line.contains("mesh.level") ? "command line (--mesh)"
                                                                                           : "from the level";
            const auto count = [&](const char* key, int n) {
                add(std::string("[mesh] ") + key, std::to_string(n), origin(std::string("mesh.") + key, from_level));
            };
            count("through_wall", m.n_wall);
            if (scene_.rest_paper) count("through_rest_paper", m.n_rest_paper);
            const MeshLevel* named = find_mesh_level(m.level);
            const MeshRule rule = mesh_rule(scene_, named ? level_target_error(*named) : 0.01);
            const int thin_wall = named ? elements_around(*named, scene_.core.inner_diameter,
                                                          scene_.core.outer_diameter)
                                        : 0;
            if (named && m.n_around > named->n_around && origin("mesh.around", from_level) == from_level) {
                // The level's count raised: for the band (mesh_rule.hpp) or so that a thin wall's cells do not lock (mesh_levels.hpp).
                const bool band = m.n_around == rule.around && rule.around > thin_wall;
                add("[mesh] around", std::to_string(m.n_around),
                    from_level + ": its " + std::to_string(named->n_around) +
                        (band ? " raised for the band's n = " + std::to_string(rule.band.n_max) +
                                    " (docs/validation/accuracy-by-level.md, \"The mesh from the band\")"
                              : " raised for the thin wall (" + significant(named->around_per_slenderness, 2) +
                                    " x 2 pi sqrt(R / t), docs/validation/accuracy-by-level.md, \"Thin walls\")"));
            } else {
                count("around", m.n_around);
            }
            if (named && m.n_along == rule.along && rule.along > kMinElementsAlong &&
                origin("mesh.along", from_level) == from_level)
                add("[mesh] along", std::to_string(m.n_along),
                    from_level + ": raised for the band's " + significant(rule.band.half_waves, 2) +
                        " axial half-waves (docs/validation/accuracy-by-level.md, \"The mesh from the band\")");
            else
                count("along", m.n_along);
            if (const auto text = mesh_rule_text(scene_)) add("[mesh] rule", *text, "scene/mesh_rule.hpp");
        }
        add("[mesh] element", toml_quoted(m.element), origin("mesh.element"));
    }
};

std::string chuck_names(const Scene& scene, auto&& has) {
    std::string out;
    for (const ChuckSpec& c : scene.supports.chucks)
        if (has(c)) out += (out.empty() ? "" : ", ") + c.name;
    return out;
}

// What one effect is in this scene, in a few words.
std::string effect_detail(const Scene& s, const std::string& effect) {
    if (effect == "core")
        return "a tube " + length(s.core.inner_diameter) + " x " + length(s.core.outer_diameter) + ", " +
               length(s.core.length) + " long, of " + s.core.material.name;
    if (effect == "rest_paper")
        return "wound paper to " + length(s.rest_paper->outer_diameter) + ", of " + s.rest_paper->material.name;
    if (effect == "rigid_clamps") {
        std::string out = "the core bore held (all displacements zero) over";
        for (const ClampSpec& c : s.supports.clamps)
            out += " z = " + length(c.z_start) + " to " + length(c.z_end) + (c.name == "left" ? " and" : "");
        return out;
    }
    if (effect == "elastic_chucks") {
        std::string out = "steel bodies and shafts inside both core ends";
        for (const ChuckSpec& c : s.supports.chucks)
            out += "; " + c.name + ": " + std::to_string(c.expanding.size()) + " expanding element(s), " +
                   (c.interface.kind == InterfaceKind::bonded                ? "bonded"
                    : c.interface.contact == ContactKind::one_sided ? "not expanded, one-sided contact"
                                                                   : "spring contact");
        return out;
    }
    if (effect == "contact_compliance")
        return "a spring layer between chuck and bore (k_n, k_t per unit area, contact law of docs/theory/chucks.md) at the " +
               chuck_names(s, [](const ChuckSpec& c) { return c.interface.kind == InterfaceKind::spring; }) +
               " chuck(s)";
    if (effect == "one_sided_contact")
        return "the bore resting on the body across the clearance, compression only, closed where gravity closes it, "
               "at the " +
               chuck_names(s, [](const ChuckSpec& c) { return c.interface.contact == ContactKind::one_sided; }) +
               " chuck(s) (not expanded; 3D solid or coupled harmonics)";
    if (effect == "gravity_preload")
        return "the static state under the weight of every part (" + std::string(kGravityText) +
               "), the modes linearised about it";
    if (effect == "bearing_springs")
        return "radial and tilting bearing springs at the " +
               chuck_names(s, [](const ChuckSpec& c) { return !c.bearing.rigid; }) + " shaft end(s)";
    if (effect == "frame_mass")
        return "a frame mass on a spring behind the " +
               chuck_names(s, [](const ChuckSpec& c) { return c.bearing.frame_mass.has_value(); }) + " bearing(s)";
    return "";
}

}  // namespace

KeySources key_sources(std::string_view case_text) {
    KeySources sources;
    try {
        const toml::table root = parse_toml_text(case_text, "");
        collect_paths(root, "", sources.in_file);
    } catch (const std::exception&) {
        // Not TOML: no key is known to come from the file.
    }
    return sources;
}

std::string describe_scene(const Scene& scene, const KeySources& sources) { return SceneRows(scene, sources).text(); }

std::string describe_effects(const Scene& scene) {
    const std::vector<std::string> effects = scene.effects();
    std::size_t width = 0;
    for (const std::string& e : effects) width = std::max(width, e.size());
    std::string out;
    for (const std::string& e : effects) {
        std::string line = "  " + e;
        line.resize(width + 5, ' ');
        out += line + effect_detail(scene, e) + "\n";
    }
    return out;
}

std::string describe_assumptions(const Scene& scene) {
    if (scene.assumptions.empty()) return "  none: the file gives every value\n";
    std::string out;
    for (const std::string& a : scene.assumptions) out += "  - " + a + "\n";
    return out;
}

std::string describe_response(const ResponseSetup& setup) {
    std::string out = describe_damping(setup.damping);
    const ExcitationSpec& x = setup.excitation;
    out += "  excitation: bow " + length(x.bow_m) + " (" + bow_shape_name(x.bow_shape) + "), unbalance " +
           format_quantity(x.unbalance_kg_m, Dimension::unbalance) + ", eccentricity " + length(x.eccentricity_m) +
           ", ovality " + length(x.ovality_m) + ", gravity " + (x.gravity ? "on" : "off") + "\n";
    const ResponseRange& r = setup.response;
    out += "  speeds: " + std::to_string(r.speeds_hz.size()) + " rotation speeds from " +
           format_quantity(r.speeds_hz.front(), Dimension::frequency) + " to " +
           format_quantity(r.speeds_hz.back(), Dimension::frequency) +
           (r.from_web_speed ? " (from web speeds at the roll's outer diameter)" : "") + "\n";
    out += "  amplitude limit: " + length(r.limit_m) + " at " + r.probes.front().name + "\n";
    for (const ResponseRange::Probe& p : r.probes) out += "  probe: " + p.name + " (z = " + length(p.z_m) + ")\n";
    return out;
}

}  // namespace coremodal
