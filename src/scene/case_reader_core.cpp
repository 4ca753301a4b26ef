// [core], [rest_paper] and their materials (library, inline, or a library
// material with some values changed) (scene/case_reader.hpp).
#include "scene/case_reader.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cstring>
#include <map>

namespace coremodal::case_reading {

namespace {

Dimension material_key_dimension(std::string_view key) {
    if (key == "density") return Dimension::density;
    if (key.starts_with("nu")) return Dimension::dimensionless;
    return Dimension::pressure;
}

double value_of(const MaterialValues& values, std::string_view key) {
    for (const MaterialValue& v : values)
        if (v.key == key) return v.value;
    return 0;
}

MaterialValues library_values(const LibraryMaterial& entry) {
    MaterialValues out;
    for (const LibraryValue& v : entry.values) out.push_back({v.key, v.value, v.source, v.assumed});
    return out;
}

// An isotropic value set written as the ten orthotropic values.
MaterialValues expand_isotropic(const MaterialValues& iso) {
    const double E = value_of(iso, "E"), nu = value_of(iso, "nu");
    const auto find = [&](std::string_view key) {
        return *std::find_if(iso.begin(), iso.end(),
                             [&](const MaterialValue& v) { return v.key == key; });
    };
    MaterialValues out;
    for (std::string_view key : orthotropic_material_keys()) {
        MaterialValue v =
            key.starts_with("E_")    ? find("E")
            : key.starts_with("nu_") ? find("nu")
            : key == "density"
                ? find("density")
                : MaterialValue{key, E / (2 * (1 + nu)), "derived: G = E / (2 (1 + nu))", false};
        v.key = key;
        out.push_back(v);
    }
    return out;
}

OrthotropicMaterial build_material(const MaterialValues& values, bool isotropic, std::string name,
                                   std::string source) {
    if (isotropic)
        return OrthotropicMaterial::isotropic(std::move(name), value_of(values, "E"),
                                              value_of(values, "nu"), value_of(values, "density"),
                                              std::move(source));
    OrthotropicMaterial m;
    m.name = std::move(name);
    m.E_r = value_of(values, "E_r");
    m.E_theta = value_of(values, "E_theta");
    m.E_z = value_of(values, "E_z");
    m.G_rtheta = value_of(values, "G_rtheta");
    m.G_rz = value_of(values, "G_rz");
    m.G_thetaz = value_of(values, "G_thetaz");
    m.nu_rtheta = value_of(values, "nu_rtheta");
    m.nu_rz = value_of(values, "nu_rz");
    m.nu_thetaz = value_of(values, "nu_thetaz");
    m.density = value_of(values, "density");
    m.source = std::move(source);
    return m;
}

}  // namespace

CoreSpec CaseReader::read_core(const Section& top, Scene& scene) const {
    const std::optional<Section> core = section(top, "core", "core");
    if (!core)
        fail(top.table->source(),
             "missing table [core]; expected [core] with inner_diameter, outer_diameter or "
             "wall, "
             "length and material");
    CoreSpec spec;
    spec.inner_diameter = required(
        *core, "inner_diameter", "the core's inner diameter, e.g. inner_diameter = \"76 mm\"");
    at_most_one(*core, "outer_diameter", "wall");
    if (const auto wall = quantity(*core, "wall"))
        spec.outer_diameter = spec.inner_diameter + 2 * *wall;
    else
        spec.outer_diameter =
            required(*core, "outer_diameter",
                     "outer_diameter or wall (exactly one), e.g. wall = \"15 mm\"");
    if (spec.inner_diameter >= spec.outer_diameter) {
        const toml::node& at = *get(*core, "inner_diameter");
        fail(at, "[core] inner_diameter = " +
                     format_quantity(spec.inner_diameter, Dimension::length) +
                     " must be smaller than [core] outer_diameter = " +
                     format_quantity(spec.outer_diameter, Dimension::length));
    }
    spec.length = required(*core, "length", "the core length, e.g. length = \"1.5 m\"");
    spec.material = read_material(*core, "core", kDefaultCoreMaterial, scene);
    return spec;
}

std::optional<RestPaperSpec> CaseReader::read_rest_paper(const Section& top, Scene& scene) const {
    const std::optional<Section> rest = section(top, "rest_paper", "rest_paper");
    if (!rest) return std::nullopt;
    RestPaperSpec spec;
    const double core_do = scene.core.outer_diameter;
    at_most_one(*rest, "outer_diameter", "thickness");
    if (const auto thickness = quantity(*rest, "thickness")) {
        spec.outer_diameter = core_do + 2 * *thickness;
    } else {
        spec.outer_diameter =
            required(*rest, "outer_diameter",
                     "thickness or outer_diameter (exactly one), e.g. thickness = \"10 mm\"");
        if (spec.outer_diameter <= core_do)
            fail(*get(*rest, "outer_diameter"),
                 "[rest_paper] outer_diameter = " +
                     format_quantity(spec.outer_diameter, Dimension::length) +
                     " must be larger than [core] outer_diameter = " +
                     format_quantity(core_do, Dimension::length));
    }
    spec.material = read_material(*rest, "rest paper", kDefaultRestPaperMaterial, scene);
    return spec;
}

OrthotropicMaterial CaseReader::read_material(const Section& owner, std::string_view role,
                                              std::string_view default_name, Scene& scene) const {
    const toml::node* node = get(owner, "material");
    const size_t warnings_before = warnings_.size();
    OrthotropicMaterial m;
    if (!node) {
        scene.assumptions.push_back(std::string(role) +
                                    " material not given: library material '" +
                                    std::string(default_name) + "' used");
        m = from_library(*find_library_material(default_name), {}, role, scene);
    } else if (node->is_string()) {
        m = from_library(library_entry(owner, "material", *node), {}, role, scene);
    } else {
        m = inline_material(*section(owner, "material", "material"), role, scene);
    }
    if (const std::optional<std::string> why = why_not_admissible(m)) {
        const toml::source_region& at = node ? node->source() : owner.table->source();
        // A value outside its plausible range is the likely cause (a bare 33 read as 33 Pa).
        std::string hint;
        for (size_t i = warnings_before; i < warnings_.size(); ++i) hint += "; likely cause: " + warnings_[i];
        fail(at, name_of(owner, "material") + " is not admissible: " + *why +
                     "; expected positive moduli and density, and Poisson ratios for which the "
                     "compliance matrix is positive definite (Jones 1999, ch. 2; docs/reference/case-scene.md)" + hint);
    }
    return m;
}

const LibraryMaterial& CaseReader::library_entry(const Section& s, std::string_view key,
                                                 const toml::node& node) const {
    const std::string name(*node.value<std::string_view>());
    if (const LibraryMaterial* entry = find_library_material(name)) return *entry;
    fail(node, echo(s, key, node) + ": unknown library material" + did_you_mean(name, library_name_list(), '"') +
                   "; expected one of " + library_names() + ", or an inline table of values");
}

OrthotropicMaterial CaseReader::from_library(const LibraryMaterial& entry,
                                             const std::map<std::string_view, double>& user,
                                             std::string_view role, Scene& scene) const {
    bool isotropic = entry.isotropic;
    MaterialValues values = library_values(entry);
    const bool orthotropic_override = std::any_of(user.begin(), user.end(), [](const auto& kv) {
        return kv.first != "density" && kv.first != "E" && kv.first != "nu";
    });
    if (isotropic && orthotropic_override) {
        values = expand_isotropic(values);
        isotropic = false;
    }
    std::vector<std::string_view> overridden;
    for (MaterialValue& v : values) {
        if (const auto it = user.find(v.key); it != user.end()) {
            v = {v.key, it->second, "", false, true};
            overridden.push_back(v.key);
        } else {
            scene.assumptions.push_back(assumption(role, entry.name, v));
        }
    }
    std::string source = "library '" + std::string(entry.name) + "'";
    std::string name(entry.name);
    if (!overridden.empty()) {
        source += ", user values for " + join(overridden);
        name += " (modified)";
    }
    return build_material(values, isotropic, name, source);
}

std::string CaseReader::assumption(std::string_view role, std::string_view material,
                                          const MaterialValue& v) {
    return std::string(role) + " material '" + std::string(material) +
           "': " + std::string(v.key) + " = " +
           format_quantity(v.value, material_key_dimension(v.key)) +
           (v.assumed ? " assumed (" : " from the library (") + std::string(v.source) + ")";
}

OrthotropicMaterial CaseReader::inline_material(const Section& mat, std::string_view role,
                                                Scene& scene) const {
    std::map<std::string_view, double> user;
    const toml::node* first_iso = nullptr;
    const toml::node* first_ortho = nullptr;
    for (std::string_view key : keys_of("material")) {
        if (key == "base") continue;
        const std::optional<double> v = quantity(mat, key);
        if (!v) continue;
        user[key] = *v;
        const bool iso_only = key == "E" || key == "nu";
        const bool ortho_only = key != "density" && !iso_only;
        if (iso_only && !first_iso) first_iso = get(mat, key);
        if (ortho_only && !first_ortho) first_ortho = get(mat, key);
    }
    if (first_iso && first_ortho)
        fail(*first_ortho,
             mat.display + " mixes isotropic keys (E, nu) with orthotropic keys (" +
                 join(orthotropic_material_keys()) + "); expected one of the two sets");
    if (const toml::node* base = get(mat, "base")) {
        const LibraryMaterial& entry = library_entry(mat, "base", *base);
        if (first_iso && !entry.isotropic)
            fail(*first_iso, mat.display +
                                 " E and nu apply to isotropic materials, but base '" +
                                 std::string(entry.name) + "' is orthotropic; expected " +
                                 join(orthotropic_material_keys()));
        return from_library(entry, user, role, scene);
    }
    return complete_inline_material(mat, user, first_ortho != nullptr);
}

OrthotropicMaterial CaseReader::complete_inline_material(const Section& mat,
                                                         const std::map<std::string_view, double>& user,
                                                         bool orthotropic) const {
    const std::vector<std::string_view>& keys =
        orthotropic ? orthotropic_material_keys() : isotropic_material_keys();
    std::vector<std::string_view> missing;
    for (std::string_view key : keys)
        if (!user.contains(key)) missing.push_back(key);
    if (!missing.empty())
        fail(mat.table->source(),
             mat.display + " is missing " + join(missing) + "; expected all of " + join(keys) +
                 (orthotropic ? " for an orthotropic material" : " for an isotropic material") +
                 ", or base = \"<library material>\" to take the rest from the library (" +
                 library_names() + ")");
    MaterialValues values;
    for (std::string_view key : keys) values.push_back({key, user.at(key), "", false, true});
    return build_material(values, !orthotropic, "user", "user");
}

}  // namespace coremodal::case_reading
