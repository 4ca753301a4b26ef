// Case file (TOML) -> Scene. Every check of user input lives here; each
// failure is an InputError that points at the line and column of the value.
//
// Reading goes table by table: the keys of each table are first checked
// against the schema (case_schema.hpp: unknown keys, value kinds), then the
// values are read, converted to SI, range-checked and checked against each other.
#include "scene/case_file.hpp"

#include "common/error.hpp"
#include "scene/case_schema.hpp"
#include "scene/case_table.hpp"
#include "scene/chuck_contact.hpp"
#include "scene/materials_library.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/toml_text.hpp"
#include "scene/units.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace coremodal {
namespace {

namespace fs = std::filesystem;

// Chuck defaults when the file does not say (each echoed as an assumption):
// a sliding fit of a fraction of a millimetre, and a short stub to the bearing.
constexpr double kDefaultChuckClearance = 0.5e-3;  // m, radial
constexpr double kDefaultShaftLength = 0.15;       // m
// The mesh generator places nodes at 0, 90, 180 and 270 degrees (symmetry
// planes of bending pairs), so the count around must split into quarters.
constexpr int kAroundMultiple = 4;
// Long values are cut in messages: the message must point, not reproduce.
constexpr std::size_t kMaxShownChars = 60;

const std::vector<std::string_view> kModelLevels = {"solid", "harmonic", "auto", "beam"};
const std::vector<std::string_view> kSupportTypes = {"free", "clamped", "chucks"};
const std::vector<std::string_view> kInterfaceKinds = {"spring", "bonded"};
const std::vector<std::string_view> kBearingTypes = {"rigid", "elastic"};
const std::vector<std::string_view> kElementTypes = {"hex20", "hex27"};

// A table of the case file, with its name in messages ("[core.material]")
// and its table in the schema ("material").
struct Section {
    const toml::table* table = nullptr;
    std::string display;  // "" for the top level
    std::string schema;
};

std::string join(const std::vector<std::string_view>& words, std::string_view separator = ", ") {
    std::string out;
    for (std::string_view w : words) {
        if (!out.empty()) out += separator;
        out += w;
    }
    return out;
}

std::string printable(std::string_view s) {
    std::string out;
    for (char c : s) out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
    return out;
}

// Shortest text that reads back as the same double: 0.07, not 0.070000000000000007.
std::string shortest(double v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
}

// The value roughly as the user wrote it, in TOML syntax.
std::string show(const toml::node& node) {
    std::string s;
    if (node.is_table()) {
        s = "{...}";
    } else if (node.is_string()) {
        s = "\"" + std::string(*node.value<std::string_view>()) + "\"";
    } else if (node.is_floating_point()) {
        s = shortest(*node.value<double>());
    } else if (const toml::array* array = node.as_array()) {
        s = "[";
        for (std::size_t i = 0; i < array->size() && s.size() <= kMaxShownChars; ++i)
            s += (i ? ", " : "") + show((*array)[i]);
        s += "]";
    } else {
        std::ostringstream out;
        node.visit([&](const auto& v) { out << v; });
        s = out.str();
    }
    s = printable(s);
    if (s.size() > kMaxShownChars) s = s.substr(0, kMaxShownChars) + "...";
    return s;
}

std::string library_names() {
    std::vector<std::string_view> names;
    for (const LibraryMaterial& m : material_library()) names.push_back(m.name);
    return join(names);
}

std::vector<std::string_view> library_name_list() {
    std::vector<std::string_view> names;
    for (const LibraryMaterial& m : material_library()) names.push_back(m.name);
    return names;
}

std::vector<std::string_view> mesh_level_names() {
    std::vector<std::string_view> names;
    for (const MeshLevel& level : kMeshLevels) names.push_back(level.name);
    return names;
}

Dimension material_key_dimension(std::string_view key) {
    if (key == "density") return Dimension::density;
    if (key.starts_with("nu")) return Dimension::dimensionless;
    return Dimension::pressure;
}

// A material value on its way from library or file to the OrthotropicMaterial.
struct MaterialValue {
    std::string_view key;
    double value = 0;
    std::string_view source;  // library citation; empty for user values
    bool assumed = false;
    bool from_user = false;
};
using MaterialValues = std::vector<MaterialValue>;

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

// One clamp zone as the file gives it, before conversion to z from the left end.
struct ClampInput {
    double length = 0;
    double offset = 0;  // start or center, from that zone's core end
    bool centred = false;
    const toml::node* where = nullptr;
};

class CaseReader {
public:
    explicit CaseReader(std::string path) : path_(std::move(path)) {}

    Scene read(const toml::table& root) {
        const Section top = open(root, "", "");
        Scene scene;
        scene.source_file = path_;
        scene.name = text(top, "name").value_or(fs::path(path_).stem().string());
        scene.description = text(top, "description").value_or("");
        scene.model = choice(top, "model", kModelLevels).value_or(scene.model);
        scene.core = read_core(top, scene);
        scene.rest_paper = read_rest_paper(top, scene);
        scene.supports = read_supports(top, scene);
        scene.analysis = read_analysis(top);
        scene.mesh = read_mesh(top, scene);
        scene.warnings = warnings_;
        return scene;
    }

private:
    std::string path_;
    // Values that parse but look like slips (check_plausible); filled by the
    // const readers as they go, so mutable.
    mutable std::vector<std::string> warnings_;

    // ---- messages -------------------------------------------------------

    std::string location(const toml::source_region& where) const {
        if (where.begin.line == 0) return path_ + ": ";
        return path_ + ":" + std::to_string(where.begin.line) + ":" +
               std::to_string(where.begin.column) + ": ";
    }

    [[noreturn]] void fail(const toml::source_region& where, const std::string& what) const {
        throw InputError(location(where) + what);
    }
    [[noreturn]] void fail(const toml::node& where, const std::string& what) const {
        fail(where.source(), what);
    }

    static std::string name_of(const Section& s, std::string_view key) {
        return s.display.empty() ? std::string(key) : s.display + " " + std::string(key);
    }
    // "[core] length = -1.5"
    static std::string echo(const Section& s, std::string_view key, const toml::node& value) {
        return name_of(s, key) + " = " + show(value);
    }

    // ---- the schema: unknown keys and value kinds ----------------------

    Section open(const toml::table& table, std::string display, std::string schema) const {
        Section s{&table, std::move(display), std::move(schema)};
        for (const auto& [key, value] : table) {
            const KeySpec* spec = find_key(s.schema, key.str());
            if (!spec) unknown_key(s, key);
            check_kind(s, *spec, value);
        }
        return s;
    }

    [[noreturn]] void unknown_key(const Section& s, const toml::key& key) const {
        const std::vector<std::string_view> valid = keys_of(s.schema);
        const std::string where = s.display.empty() ? "at the top level" : "in " + s.display;
        std::string msg = "unknown key '" + printable(key.str()) + "' " + where;
        if (const std::string_view near = nearest(key.str(), valid); !near.empty())
            msg += "; did you mean '" + std::string(near) + "'?";
        else
            msg += "; expected one of " + join(valid);
        fail(key.source(), msg);
    }

    void check_kind(const Section& s, const KeySpec& spec, const toml::node& value) const {
        const std::string what = echo(s, spec.key, value) + ": ";
        switch (spec.kind) {
            case ValueKind::quantity:
                if (!value.is_number() && !value.is_string())
                    fail(value, what + "expected " + quantity_hint(spec.dimension));
                return;
            case ValueKind::integer:
                if (value.is_floating_point())
                    fail(value, what + "expected a whole number (no decimal point)");
                if (!value.is_integer()) fail(value, what + "expected a whole number");
                return;
            case ValueKind::text:
                if (!value.is_string()) fail(value, what + "expected a string in quotes");
                return;
            case ValueKind::table:
                if (!value.is_table())
                    fail(value, what + "expected a table, written [" +
                                    (s.display.empty() ? std::string(spec.key)
                                                       : s.schema + "." + std::string(spec.key)) +
                                    "] followed by its keys");
                return;
            case ValueKind::material:
                if (!value.is_string() && !value.is_table())
                    fail(value, what + "expected a library material in quotes (" + library_names() +
                                    ") or an inline table such as { base = \"" +
                                    std::string(kDefaultCoreMaterial) + "\", E_z = \"6 GPa\" }");
                return;
            case ValueKind::boolean:
                if (!value.is_boolean()) fail(value, what + "expected true or false (no quotes)");
                return;
            case ValueKind::tables:
                if (!value.is_array_of_tables())
                    fail(value, what + "expected tables written [[" + s.schema + "." + std::string(spec.key) +
                                    "]] (double brackets), one per item");
                return;
            case ValueKind::list:
                if (!value.is_array()) fail(value, what + "expected a list in brackets, e.g. [1, 2]");
                return;
            case ValueKind::band:
                if (!value.is_array())
                    fail(value,
                         what + "expected two frequencies, e.g. band = [\"0 Hz\", \"500 Hz\"]");
                return;
        }
    }

    static std::string quantity_hint(Dimension d) {
        if (d == Dimension::dimensionless) return "a plain number";
        const std::string name = dimension_name(d);
        return (name.front() == 'a' ? "an " : "a ") + name + ": a plain number in " + si_unit(d) +
               " or a string with a unit (" + accepted_units(d) + "), e.g. \"" + example_of(d) +
               "\"";
    }

    static std::string example_of(Dimension d) {
        switch (d) {
            case Dimension::length:
                return "76 mm";
            case Dimension::pressure:
                return "6.5 GPa";
            case Dimension::density:
                return "920 kg/m^3";
            case Dimension::frequency:
                return "500 Hz";
            default:
                return std::string("1 ") + si_unit(d);
        }
    }

    // ---- typed values ---------------------------------------------------

    static const toml::node* get(const Section& s, std::string_view key) {
        return s.table->get(key);
    }

    std::optional<std::string> text(const Section& s, std::string_view key) const {
        const toml::node* node = get(s, key);
        if (!node) return std::nullopt;
        return std::string(*node->value<std::string_view>());
    }

    // A value from a fixed list; suggests the nearest on a typo.
    std::optional<std::string> choice(const Section& s, std::string_view key,
                                      const std::vector<std::string_view>& allowed) const {
        const std::optional<std::string> value = text(s, key);
        if (!value) return std::nullopt;
        if (std::find(allowed.begin(), allowed.end(), *value) != allowed.end()) return value;
        std::string msg = echo(s, key, *get(s, key)) + ": unknown value";
        if (const std::string_view near = nearest(*value, allowed); !near.empty())
            msg += "; did you mean \"" + std::string(near) + "\"?";
        fail(*get(s, key), msg + "; expected one of " + join(allowed));
    }

    // A quantity node converted to SI (no range check).
    double to_si(const toml::node& node, Dimension d, const std::string& what) const {
        if (node.is_number()) {
            const double v = *node.value<double>();
            if (!std::isfinite(v)) fail(node, what + ": expected a finite number");
            return v;
        }
        if (!node.is_string()) fail(node, what + ": expected " + quantity_hint(d));
        try {
            return parse_quantity(*node.value<std::string_view>(), d);
        } catch (const std::invalid_argument& e) {
            fail(node, what + ": " + e.what());
        }
    }

    std::optional<double> quantity(const Section& s, std::string_view key) const {
        const toml::node* node = get(s, key);
        if (!node) return std::nullopt;
        const KeySpec* spec = find_key(s.schema, key);
        COREMODAL_ASSERT(spec && spec->kind == ValueKind::quantity);
        const double v = to_si(*node, spec->dimension, echo(s, key, *node));
        check_range(s, *spec, *node, v);
        check_plausible(s, *spec, *node, v);
        return v;
    }

    // Outside the key's plausible range: a warning (Scene::warnings), with the
    // unit a plain number was probably meant in.
    void check_plausible(const Section& s, const KeySpec& spec, const toml::node& node, double v) const {
        const PlausibleRange& p = spec.plausible;
        if (p.empty() || (v >= p.low && v <= p.high)) return;
        std::string msg = location(node.source()) + name_of(s, spec.key) + " = " +
                          format_quantity(v, spec.dimension) + " is outside the plausible range " +
                          format_quantity(p.low, spec.dimension) + " to " + format_quantity(p.high, spec.dimension) +
                          " (" + std::string(p.why) + ")";
        if (node.is_number()) {
            msg += std::string("; plain numbers are in ") + si_unit(spec.dimension);
            if (const std::optional<std::string> unit = likely_unit(v, spec.dimension, p))
                msg += ": did you mean \"" + show(node) + " " + *unit + "\"?";
        }
        msg += "; the run goes on with the value as read";
        if (std::find(warnings_.begin(), warnings_.end(), msg) == warnings_.end()) warnings_.push_back(msg);
    }

    // The common unit that brings a plain number v inside the range, nearest
    // the typical value (on a log scale).
    static std::optional<std::string> likely_unit(double v, Dimension d, const PlausibleRange& p) {
        std::optional<std::string> best;
        double best_distance = 0;
        for (const UnitFactor& u : common_units(d)) {
            const double candidate = v * u.to_si;
            if (u.to_si == 1.0 || candidate < p.low || candidate > p.high) continue;
            const double distance = std::abs(std::log10(candidate / p.typical));
            if (!best || distance < best_distance) best = std::string(u.symbol), best_distance = distance;
        }
        return best;
    }

    void check_range(const Section& s, const KeySpec& spec, const toml::node& node,
                     double v) const {
        const std::string what = name_of(s, spec.key) + " = " + format_quantity(v, spec.dimension);
        if (spec.min_exclusive && !(v > spec.min))
            fail(node,
                 what + " must be " +
                     (spec.min == 0 ? std::string("positive")
                                    : "larger than " + format_quantity(spec.min, spec.dimension)));
        if (!spec.min_exclusive && v < spec.min)
            fail(node,
                 what + " must be " +
                     (spec.min == 0 ? std::string("zero or positive")
                                    : "at least " + format_quantity(spec.min, spec.dimension)));
        if (v > spec.max) {
            std::string msg = what + " is too large: expected at most " +
                              format_quantity(spec.max, spec.dimension);
            if (node.is_number() && spec.dimension != Dimension::dimensionless)
                msg += std::string("; plain numbers are in ") + si_unit(spec.dimension) +
                       (spec.dimension == Dimension::length
                            ? ", for millimetres write \"" + show(node) + " mm\""
                            : "");
            fail(node, msg);
        }
    }

    std::optional<int> integer(const Section& s, std::string_view key) const {
        const toml::node* node = get(s, key);
        if (!node) return std::nullopt;
        const KeySpec* spec = find_key(s.schema, key);
        COREMODAL_ASSERT(spec && spec->kind == ValueKind::integer);
        const std::int64_t v = *node->value<std::int64_t>();
        // Compared as doubles: the bounds are far inside both ranges.
        if (static_cast<double>(v) < spec->min || static_cast<double>(v) > spec->max)
            fail(*node, echo(s, key, *node) + " is out of range; expected " +
                            std::to_string(static_cast<long long>(spec->min)) + " to " +
                            std::to_string(static_cast<long long>(spec->max)));
        return static_cast<int>(v);
    }

    std::optional<Section> section(const Section& parent, std::string_view key,
                                   std::string schema) const {
        const toml::node* node = get(parent, key);
        if (!node) return std::nullopt;
        const std::string display = parent.display.empty()
                                        ? "[" + std::string(key) + "]"
                                        : parent.display.substr(0, parent.display.size() - 1) +
                                              "." + std::string(key) + "]";
        return open(*node->as_table(), display, std::move(schema));
    }

    double required(const Section& s, std::string_view key, const std::string& expected) const {
        if (const std::optional<double> v = quantity(s, key)) return *v;
        fail(s.table->source(),
             s.display + " " + std::string(key) + " is missing; expected " + expected);
    }

    // At most one of two alternatives (wall or outer_diameter, start or center).
    void at_most_one(const Section& s, std::string_view a, std::string_view b) const {
        if (get(s, a) && get(s, b))
            fail(*get(s, b), echo(s, b, *get(s, b)) + " and " + echo(s, a, *get(s, a)) +
                                 " are both given; expected exactly one of them");
    }

    // ---- [core] ---------------------------------------------------------

    CoreSpec read_core(const Section& top, Scene& scene) const {
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

    // ---- [rest_paper] ---------------------------------------------------

    std::optional<RestPaperSpec> read_rest_paper(const Section& top, Scene& scene) const {
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

    // ---- materials ------------------------------------------------------

    OrthotropicMaterial read_material(const Section& owner, std::string_view role,
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
                         "compliance matrix is positive definite (DOMAIN.md §6)" + hint);
        }
        return m;
    }

    const LibraryMaterial& library_entry(const Section& s, std::string_view key,
                                         const toml::node& node) const {
        const std::string name(*node.value<std::string_view>());
        if (const LibraryMaterial* entry = find_library_material(name)) return *entry;
        std::string msg = echo(s, key, node) + ": unknown library material";
        if (const std::string_view near = nearest(name, library_name_list()); !near.empty())
            msg += "; did you mean \"" + std::string(near) + "\"?";
        fail(node, msg + "; expected one of " + library_names() + ", or an inline table of values");
    }

    // A library material, some values overridden by the user; every value the
    // user did not give becomes an assumption sentence.
    OrthotropicMaterial from_library(const LibraryMaterial& entry,
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

    static std::string assumption(std::string_view role, std::string_view material,
                                  const MaterialValue& v) {
        return std::string(role) + " material '" + std::string(material) +
               "': " + std::string(v.key) + " = " +
               format_quantity(v.value, material_key_dimension(v.key)) +
               (v.assumed ? " assumed (" : " from the library (") + std::string(v.source) + ")";
    }

    OrthotropicMaterial inline_material(const Section& mat, std::string_view role,
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

    OrthotropicMaterial complete_inline_material(const Section& mat,
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

    // ---- [supports] -----------------------------------------------------

    SupportSpec read_supports(const Section& top, Scene& scene) const {
        SupportSpec spec;
        const double core_length = scene.core.length;
        const std::optional<Section> supports = section(top, "supports", "supports");
        if (!supports) return spec;
        // The type decides the schema of [supports.left] and [supports.right].
        const std::string type = choice(*supports, "type", kSupportTypes).value_or("free");
        const std::string end_schema = type == "chucks" ? "chuck" : "clamp";
        const std::optional<Section> left = section(*supports, "left", end_schema);
        const std::optional<Section> right = section(*supports, "right", end_schema);
        if (type == "free") {
            if (left || right)
                fail((left ? left : right)->table->source(),
                     (left ? left : right)->display +
                         " is given but [supports] type is \"free\"; "
                         "expected type = \"clamped\" or \"chucks\", or remove the table");
            return spec;
        }
        if (type == "chucks") return read_chucks(*supports, left, right, scene);
        spec.kind = SupportKind::clamped;
        if (!left)
            fail(supports->table->source(),
                 "[supports] type = \"clamped\" needs [supports.left]; expected e.g. "
                 "[supports.left] length = \"70 mm\" (right mirrors left unless given)");
        const ClampInput left_in = read_clamp(*left);
        const ClampInput right_in = right ? read_clamp(*right) : left_in;
        spec.clamps.push_back(place_clamp("left", left_in, core_length, false));
        spec.clamps.push_back(place_clamp("right", right_in, core_length, true));
        check_no_overlap(spec.clamps[0], spec.clamps[1], right ? right_in.where : left_in.where);
        return spec;
    }

    // ---- [supports] type = "chucks" -------------------------------------

    SupportSpec read_chucks(const Section& supports, const std::optional<Section>& left,
                            const std::optional<Section>& right, Scene& scene) const {
        if (!left)
            fail(supports.table->source(),
                 "[supports] type = \"chucks\" needs [supports.left]; expected e.g. [supports.left] "
                 "inserted_length = \"110 mm\" with [[supports.left.expanding]] center = \"70 mm\" "
                 "width = \"40 mm\" (right mirrors left unless given)");
        SupportSpec spec;
        spec.kind = SupportKind::chucks;
        spec.chucks.push_back(read_chuck(*left, "left", scene));
        if (right) {
            spec.chucks.push_back(read_chuck(*right, "right", scene));
        } else {
            ChuckSpec mirrored = spec.chucks.front();
            mirrored.name = "right";
            spec.chucks.push_back(mirrored);
        }
        return spec;
    }

    ChuckSpec read_chuck(const Section& s, std::string name, Scene& scene) const {
        ChuckSpec c;
        c.name = std::move(name);
        const double bore = scene.core.inner_diameter, length = scene.core.length;
        c.inserted_length = required(s, "inserted_length",
                                     "the chuck length inside the core, e.g. inserted_length = \"110 mm\"");
        if (c.inserted_length > length / 2)
            fail(*get(s, "inserted_length"),
                 echo(s, "inserted_length", *get(s, "inserted_length")) + " is longer than half the core ([core] "
                 "length = " + format_quantity(length, Dimension::length) +
                 "); expected the two chucks not to meet, inserted_length <= " +
                 format_quantity(length / 2, Dimension::length));
        at_most_one(s, "clearance", "body_diameter");
        if (const auto d = quantity(s, "body_diameter")) {
            c.body_diameter = *d;
            if (c.body_diameter > bore)
                fail(*get(s, "body_diameter"),
                     echo(s, "body_diameter", *get(s, "body_diameter")) + " is larger than the core bore "
                     "([core] inner_diameter = " + format_quantity(bore, Dimension::length) +
                     "); expected a chuck body that fits inside the core (at most the bore: zero clearance)");
        } else {
            const double clearance = quantity(s, "clearance").value_or(kDefaultChuckClearance);
            if (!get(s, "clearance"))
                scene.assumptions.push_back("chuck " + c.name + ": radial clearance " +
                                            format_quantity(kDefaultChuckClearance, Dimension::length) +
                                            " assumed (body diameter = bore - 2 x clearance)");
            c.body_diameter = bore - 2 * clearance;
            if (c.body_diameter <= 0.2 * bore)
                fail(*get(s, "clearance"), echo(s, "clearance", *get(s, "clearance")) +
                                               " leaves no chuck body; expected a radial clearance of "
                                               "a fraction of a millimetre to a few millimetres");
        }
        c.shaft_diameter = quantity(s, "shaft_diameter").value_or(c.body_diameter);
        // The shaft leaves the body's end face: it cannot be wider than the body.
        if (c.shaft_diameter > c.body_diameter * (1 + 1e-9))
            fail(*get(s, "shaft_diameter"),
                 echo(s, "shaft_diameter", *get(s, "shaft_diameter")) + " is wider than the chuck body (" +
                     format_quantity(c.body_diameter, Dimension::length) +
                     "); expected at most the body diameter (the shaft leaves the body's end face)");
        if (!get(s, "shaft_diameter"))
            scene.assumptions.push_back("chuck " + c.name + ": shaft diameter = chuck body diameter (" +
                                        format_quantity(c.body_diameter, Dimension::length) + ") assumed");
        c.shaft_length = quantity(s, "shaft_length").value_or(kDefaultShaftLength);
        if (!get(s, "shaft_length"))
            scene.assumptions.push_back("chuck " + c.name + ": shaft length (core end to bearing) " +
                                        format_quantity(kDefaultShaftLength, Dimension::length) + " assumed");
        c.material = read_material(s, "chuck " + c.name, kDefaultChuckMaterial, scene);
        c.expanding = read_expanding(s, c);
        c.interface = read_interface(s, c.name, scene);
        c.bearing = read_bearing(s, c.name, scene);
        return c;
    }

    std::vector<ExpandingElement> read_expanding(const Section& chuck, const ChuckSpec& c) const {
        const toml::node* node = get(chuck, "expanding");
        if (!node)
            fail(chuck.table->source(),
                 chuck.display + " has no expanding elements; expected at least one, e.g. [[" +
                     chuck.display.substr(1, chuck.display.size() - 2) +
                     ".expanding]] center = \"70 mm\" width = \"40 mm\"");
        std::vector<ExpandingElement> out;
        const toml::array& items = *node->as_array();
        for (size_t i = 0; i < items.size(); ++i) {
            const std::string display = chuck.display.substr(0, chuck.display.size() - 1) + ".expanding #" +
                                        std::to_string(i + 1) + "]";
            const Section e = open(*items[i].as_table(), display, "expanding");
            ExpandingElement x;
            x.center = required(e, "center", "the element's axial centre from the core end, e.g. center = \"70 mm\"");
            x.width = required(e, "width", "the element's axial width, e.g. width = \"40 mm\"");
            const double near = x.center - x.width / 2, far = x.center + x.width / 2;
            if (near < -1e-12 || far > c.inserted_length + 1e-12)
                fail(*get(e, "center"),
                     display + " spans " + format_quantity(near, Dimension::length) + " to " +
                         format_quantity(far, Dimension::length) + " from the core end, outside the inserted "
                         "length 0 to " + format_quantity(c.inserted_length, Dimension::length) +
                         "; expected the element on the chuck body inside the core");
            if (const auto n = integer(e, "segments")) {
                x.segments = *n;
                x.segment_angle = required(e, "segment_angle",
                                           "the angle each segment spans, e.g. segment_angle = \"60 deg\"");
                if (x.segments * x.segment_angle > 2 * M_PI + 1e-9)
                    fail(*get(e, "segment_angle"),
                         display + " " + std::to_string(x.segments) + " segments of " +
                             format_quantity(x.segment_angle * 180 / M_PI, Dimension::dimensionless) +
                             " deg overlap (more than 360 deg in all); expected segments x segment_angle <= 360 deg");
            } else if (const toml::node* a = get(e, "segment_angle")) {
                fail(*a, echo(e, "segment_angle", *a) + " without segments; expected segments = N as well, "
                                                        "or neither for a full band");
            }
            for (const ExpandingElement& other : out)
                if (std::abs(other.center - x.center) < (other.width + x.width) / 2)
                    fail(*get(e, "center"), display + " overlaps an earlier expanding element of the same chuck; "
                                                      "expected separate elements");
            out.push_back(x);
        }
        return out;
    }

    ChuckInterface read_interface(const Section& s, const std::string& chuck, Scene& scene) const {
        ChuckInterface f;
        const std::string kind = choice(s, "interface", kInterfaceKinds).value_or("spring");
        f.kind = kind == "bonded" ? InterfaceKind::bonded : InterfaceKind::spring;
        if (const toml::node* e = get(s, "expanded")) f.expanded = *e->value<bool>();
        const toml::node* kn = get(s, "normal_stiffness");
        const toml::node* kt = get(s, "tangential_stiffness");
        const toml::node* p = get(s, "expansion_pressure");
        if (f.kind == InterfaceKind::bonded) {
            for (const toml::node* n : {kn, kt, p, get(s, "expanded")})
                if (n)
                    fail(*n, s.display + " interface = \"bonded\" takes no stiffness, pressure or expanded state; "
                                         "expected interface = \"spring\" for a compliant contact");
            return f;
        }
        if (p && kn)
            fail(*p, s.display + " gives both expansion_pressure and normal_stiffness; expected one of them "
                                 "(the pressure is converted to a stiffness, docs/chucks.md)");
        if (p && !f.expanded)
            fail(*p, s.display + " expansion_pressure with expanded = false; expected no pressure for a chuck that "
                                 "was not expanded");
        const ContactLaw& law = contact_law();
        if (kn) {
            f.normal_stiffness = *quantity(s, "normal_stiffness");
        } else {
            const double pressure = !f.expanded ? 0.0 : quantity(s, "expansion_pressure").value_or(law.default_pressure);
            if (f.expanded) f.expansion_pressure = pressure;
            f.normal_stiffness = contact_normal_stiffness(pressure, law);
            scene.assumptions.push_back(
                "chuck " + chuck + ": interface normal stiffness " +
                format_quantity(f.normal_stiffness, Dimension::stiffness_per_area) + " from " +
                (f.expanded ? "expansion pressure " + format_quantity(pressure, Dimension::pressure) +
                                  (p ? "" : " (assumed)")
                            : std::string("a chuck not expanded (residual contact pressure ") +
                                  format_quantity(law.residual_pressure, Dimension::pressure) + ")") +
                ": k_n = K2 (p + p_res) / h with K2 = " + format_quantity(law.stack_exponent, Dimension::dimensionless) +
                ", h = " + format_quantity(law.layer_thickness, Dimension::length) + " (docs/chucks.md)");
        }
        if (kt) {
            f.tangential_stiffness = *quantity(s, "tangential_stiffness");
        } else {
            f.tangential_stiffness = contact_tangential_ratio(law) * f.normal_stiffness;
            scene.assumptions.push_back("chuck " + chuck + ": interface tangential stiffness " +
                                        format_quantity(f.tangential_stiffness, Dimension::stiffness_per_area) +
                                        " = Mindlin's ratio 2(1-nu)/(2-nu) with nu = 0.3 times the normal stiffness");
        }
        return f;
    }

    BearingSpec read_bearing(const Section& chuck, const std::string& name, Scene& scene) const {
        BearingSpec b;
        const std::optional<Section> s = section(chuck, "bearing", "bearing");
        if (!s) {
            scene.assumptions.push_back("chuck " + name + ": no [bearing] given: rigid bearing (shaft end held)");
            return b;
        }
        const std::string type = choice(*s, "type", kBearingTypes).value_or(get(*s, "radial_stiffness") ? "elastic" : "rigid");
        if (type == "rigid") {
            for (std::string_view key : {"radial_stiffness", "tilting_stiffness", "frame_mass", "frame_stiffness"})
                if (const toml::node* n = get(*s, key))
                    fail(*n, echo(*s, key, *n) + " with a rigid bearing; expected type = \"elastic\" for springs");
            return b;
        }
        b.rigid = false;
        b.radial_stiffness = required(*s, "radial_stiffness", "the bearing's radial stiffness, e.g. radial_stiffness = \"200 kN/mm\"");
        b.tilting_stiffness = required(*s, "tilting_stiffness",
                                       "the bearing's tilting stiffness, e.g. tilting_stiffness = \"1 MN*m/rad\"");
        b.frame_mass = quantity(*s, "frame_mass");
        b.frame_stiffness = quantity(*s, "frame_stiffness");
        if (b.frame_mass && !b.frame_stiffness)
            fail(*get(*s, "frame_mass"), s->display + " frame_mass without frame_stiffness; expected the frame's "
                                                      "stiffness to ground too, e.g. frame_stiffness = \"50 kN/mm\"");
        if (b.frame_stiffness && !b.frame_mass)
            fail(*get(*s, "frame_stiffness"), s->display + " frame_stiffness without frame_mass; expected the frame "
                                                           "mass too, e.g. frame_mass = \"80 kg\"");
        return b;
    }

    ClampInput read_clamp(const Section& zone) const {
        ClampInput in;
        in.length = required(zone, "length", "the clamped length, e.g. length = \"70 mm\"");
        in.where = get(zone, "length");
        at_most_one(zone, "start", "center");
        if (const auto center = quantity(zone, "center")) {
            in.centred = true;
            in.offset = *center;
            in.where = get(zone, "center");
        } else if (const auto start = quantity(zone, "start")) {
            in.offset = *start;
            in.where = get(zone, "start");
        }
        return in;
    }

    // z from the left core end; the right zone is measured from the right end.
    ClampSpec place_clamp(std::string name, const ClampInput& in, double core_length,
                          bool mirrored) const {
        const double near = in.centred ? in.offset - in.length / 2 : in.offset;
        const double far = near + in.length;
        const std::string zone = "[supports." + name + "]";
        if (near < 0)
            fail(*in.where, zone + " center = " + format_quantity(in.offset, Dimension::length) +
                                " with length = " + format_quantity(in.length, Dimension::length) +
                                " starts outside the core end; expected center >= length / 2 = " +
                                format_quantity(in.length / 2, Dimension::length));
        if (far > core_length)
            fail(*in.where, zone + " ends " + format_quantity(far, Dimension::length) +
                                " from its core end, beyond [core] length = " +
                                format_quantity(core_length, Dimension::length) +
                                "; expected the clamp zone inside the core");
        ClampSpec clamp{std::move(name), near, far};
        if (mirrored) clamp = {clamp.name, core_length - far, core_length - near};
        return clamp;
    }

    void check_no_overlap(const ClampSpec& left, const ClampSpec& right,
                          const toml::node* where) const {
        if (left.z_end <= right.z_start) return;
        const auto range = [](const ClampSpec& c) {
            return "z = " + format_quantity(c.z_start, Dimension::length) + " to " +
                   format_quantity(c.z_end, Dimension::length);
        };
        fail(*where, "[supports.left] (" + range(left) + ") and [supports.right] (" + range(right) +
                         ") overlap; expected separate clamp zones, the left one ending before the "
                         "right one starts");
    }

    // ---- [analysis] -----------------------------------------------------

    AnalysisSpec read_analysis(const Section& top) const {
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

    void read_band(const Section& s, const toml::node& node, AnalysisSpec& spec) const {
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

    // ---- [mesh] ---------------------------------------------------------

    MeshSpec read_mesh(const Section& top, const Scene& scene) const {
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
        spec.n_around = level.n_around;
        if (mesh) apply_mesh_overrides(*mesh, spec);
        if (mesh && get(*mesh, "along")) return spec;
        const std::optional<int> along = elements_along(
            scene.core.length, scene.core.outer_diameter, spec.n_around, level.axial_aspect);
        if (!along)
            fail(mesh ? mesh->table->source() : top.table->source(),
                 "[mesh] level = \"" + spec.level + "\" would need more than " +
                     std::to_string(kMaxElementsAlong) + " elements along [core] length = " +
                     format_quantity(scene.core.length, Dimension::length) +
                     "; expected a shorter core, or give [mesh] along");
        spec.n_along = *along;
        return spec;
    }

    const MeshLevel& mesh_level(const std::optional<Section>& mesh) const {
        const std::string name =
            mesh ? choice(*mesh, "level", mesh_level_names()).value_or("default") : "default";
        return *find_mesh_level(name);
    }

    void apply_mesh_overrides(const Section& mesh, MeshSpec& spec) const {
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

    std::string read_mesh_file(const Section& mesh) const {
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
};

}  // namespace

Scene parse_case_table(const toml::table& root, const std::string& path) {
    if (const toml::node* winder = root.get("winder"))
        throw InputError(path + ":" + std::to_string(winder->source().begin.line) +
                         ": [winder] is a two-drum winder file, not a roll's case file; run it with "
                         "`coremodal winder " + path + "` (docs/winder.md)");
    return CaseReader(path).read(root);
}

Scene parse_case_text(std::string_view text, const std::string& path) {
    const toml::table root = parse_toml_input(text, path, "a valid TOML case file (docs/case-files.md)");
    try {
        return parse_case_table(root, path);
    } catch (const InputError& e) {  // a key echoed in a message: the user's characters
        throw InputError(restore_characters(e.what()));
    }
}

Scene parse_case_file(const std::string& path) { return parse_case_text(read_input_file(path, "case file"), path); }

}  // namespace coremodal
