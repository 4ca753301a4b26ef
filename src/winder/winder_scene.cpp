#include "winder/winder_scene.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "common/join.hpp"
#include "scene/case_json_schema.hpp"  // quantity_pattern, the draft
#include "scene/case_key_ranges.hpp"
#include "scene/case_name.hpp"
#include "scene/case_reader.hpp"       // case_reading::show
#include "scene/case_schema.hpp"       // nearest: the "did you mean" of every case file
#include "scene/materials_library.hpp"
#include "scene/toml_text.hpp"
#include "scene/units.hpp"

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace coremodal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Hard limits catch unit slips (a plain 850 is 850 m, not 850 mm), not
// physics: the typical ranges are beside the defaults in winder_scene.hpp.
constexpr double kMaxStiffness = 1e13;  // N/m, a bearing stiffer than any steel housing
constexpr double kMaxLineLoad = 1e6;   // N/m, 1000 kN/m: far above any winder nip
constexpr double kMaxDamping = 0.9;    // a ratio near 1 is no longer a lightly damped mode

enum class Kind { quantity, integer, text, table };

struct Spec {
    std::string_view table, key;
    Kind kind;
    Dimension dimension = Dimension::dimensionless;
    double min = -kInf, max = kInf;
    bool min_exclusive = false;
    std::string_view what = "";  // how to name the quantity when not its dimension ("a line load")
    // Where the default comes from: "paper" (Jorkama & von Hertzen's example),
    // "assumed" (ours: listed in the results), "" (a setting, not physics).
    std::string_view origin = "";
};

constexpr std::string_view kPaper = "paper", kAssumed = "assumed";

Spec length(std::string_view t, std::string_view k, std::string_view origin, bool open = true) {
    return {t, k, Kind::quantity, Dimension::length, 0.0, k == "length" || k == "width" ? key_ranges::kMaxLength
                                                                              : key_ranges::kMaxDiameter,
            open, "", origin};
}
Spec positive(std::string_view t, std::string_view k, Dimension d, double max, std::string_view origin) {
    return {t, k, Kind::quantity, d, 0.0, max, true, "", origin};
}
Spec line_load(std::string_view t, std::string_view k, std::string_view origin) {
    return {t, k, Kind::quantity, Dimension::stiffness, 0.0, kMaxLineLoad, false, "a line load", origin};
}
Spec ratio(std::string_view t, std::string_view k, double max, std::string_view origin) {
    return {t, k, Kind::quantity, Dimension::dimensionless, 0.0, max, false, "", origin};
}
Spec whole(std::string_view t, std::string_view k, double min, double max, std::string_view origin = "") {
    return {t, k, Kind::integer, Dimension::dimensionless, min, max, false, "", origin};
}
Spec plain(std::string_view t, std::string_view k, Kind kind, std::string_view origin = "") {
    return {t, k, kind, Dimension::dimensionless, -kInf, kInf, false, "", origin};
}

const std::vector<Spec>& schema() {
    static const std::vector<Spec> s = {
        plain("", "name", Kind::text), plain("", "description", Kind::text), plain("", "winder", Kind::table),
        positive("winder", "web_speed", Dimension::speed, key_ranges::kMaxWebSpeed, kAssumed),
        plain("winder", "drums", Kind::table), plain("winder", "rolls", Kind::table),
        plain("winder", "rider", Kind::table), plain("winder", "damping", Kind::table),
        plain("winder", "sweep", Kind::table),
        length("winder.drums", "outer_diameter", kPaper), length("winder.drums", "wall", kPaper),
        length("winder.drums", "length", kPaper), length("winder.drums", "gap", kAssumed),
        plain("winder.drums", "material", Kind::text, kAssumed),
        positive("winder.drums", "bearing_stiffness", Dimension::stiffness, kMaxStiffness, kAssumed),
        positive("winder.drums", "bearing_stiffness_horizontal", Dimension::stiffness, kMaxStiffness, kAssumed),
        line_load("winder.drums", "line_load", ""), whole("winder.drums", "elements", 4, 400),
        whole("winder.rolls", "count", 1, 50, kPaper), length("winder.rolls", "width", kPaper),
        length("winder.rolls", "gap", kAssumed, false), length("winder.rolls", "core_inner_diameter", kAssumed),
        length("winder.rolls", "core_outer_diameter", kAssumed),
        plain("winder.rolls", "core_material", Kind::text, kAssumed),
        plain("winder.rolls", "paper_material", Kind::text, kAssumed),
        positive("winder.rolls", "paper_density", Dimension::density, 1e5, kAssumed),
        positive("winder.rolls", "radial_modulus", Dimension::pressure, 1e13, kPaper),
        {"winder.rolls", "poisson", Kind::quantity, Dimension::dimensionless, 0.0, 0.49, false, "", kPaper},
        plain("winder.rolls", "model", Kind::text), length("winder.rolls", "diameter_start", kPaper),
        length("winder.rolls", "diameter_end", kPaper),
        length("winder.rider", "outer_diameter", kAssumed), length("winder.rider", "wall", kAssumed),
        length("winder.rider", "length", kPaper), plain("winder.rider", "material", Kind::text, kAssumed),
        positive("winder.rider", "support_stiffness", Dimension::stiffness, kMaxStiffness, kAssumed),
        line_load("winder.rider", "line_load", kAssumed), whole("winder.rider", "elements", 2, 400),
        ratio("winder.damping", "drums", kMaxDamping, kAssumed), ratio("winder.damping", "nips", kMaxDamping, kAssumed),
        ratio("winder.damping", "rider", kMaxDamping, kAssumed),
        whole("winder.sweep", "points", 2, 2000), whole("winder.sweep", "harmonics", 1, 12, kPaper),
        positive("winder.sweep", "max_frequency", Dimension::frequency, 1e5, ""),
        plain("winder.sweep", "response_drum", Kind::text), plain("winder.sweep", "response_direction", Kind::text),
    };
    return s;
}

const Spec* find_spec(std::string_view table, std::string_view key) {
    for (const Spec& s : schema())
        if (s.table == table && s.key == key) return &s;
    return nullptr;
}

std::vector<std::string_view> keys_in(std::string_view table) {
    std::vector<std::string_view> keys;
    for (const Spec& s : schema())
        if (s.table == table) keys.push_back(s.key);
    return keys;
}

class WinderReader {
public:
    explicit WinderReader(std::string path) : path_(std::move(path)) {}

    WinderScene read(const toml::table& root) {
        check_table(root, "");
        WinderScene scene;
        scene.source_file = path_;
        scene.name = text(root, "", "name").value_or(std::filesystem::path(path_).stem().string());
        if (const std::string problem = case_name_problem(scene.name); !problem.empty()) {
            if (const toml::node* given = root.get("name"))
                fail(given->source(),
                     "name = " + case_reading::show(*given) + " " + problem + "; " + kCaseNameExpected);
            throw InputError(path_ + ": the case's name is its file name, '" + scene.name + "', which " + problem +
                             "; give the case a name = \"...\" (" + kCaseNameExpected + ")");
        }
        scene.description = text(root, "", "description").value_or("");
        const toml::table* winder = root["winder"].as_table();
        if (!winder) fail(root.source(), "no [winder] table; expected a winder case file (docs/how-to/winder.md)");
        take(*winder, "winder", "web_speed", scene.web_speed);
        read_drums(sub(*winder, "drums"), scene.drums);
        read_rolls(sub(*winder, "rolls"), scene.rolls);
        read_rider(sub(*winder, "rider"), scene.rider);
        read_damping(sub(*winder, "damping"), scene.damping);
        read_sweep(sub(*winder, "sweep"), scene.sweep);
        check_geometry(*winder, scene);
        scene.defaults = std::move(defaults_);
        return scene;
    }

private:
    std::string path_;
    const toml::table empty_;
    std::vector<std::string> defaults_;  // "[winder.drums] gap = 0.1 m (assumed)"

    [[noreturn]] void fail(const toml::source_region& where, const std::string& what) const {
        const std::string at = where.begin.line == 0 ? path_ + ": "
                                                     : path_ + ":" + std::to_string(where.begin.line) + ":" +
                                                           std::to_string(where.begin.column) + ": ";
        throw InputError(at + what);
    }

    static std::string display(std::string_view table, std::string_view key) {
        std::string out;
        if (!table.empty()) out.append("[").append(table).append("] ");
        return out.append(key);
    }

    // Unknown keys and value kinds of one table, then its sub-tables' own checks.
    void check_table(const toml::table& t, std::string_view table) const {
        for (const auto& [key, value] : t) {
            const Spec* spec = find_spec(table, key.str());
            if (!spec) {
                const auto valid = keys_in(table);
                std::string msg = "unknown key '" + std::string(key.str()) + "' " +
                                  (table.empty() ? std::string("at the top level") : "in [" + std::string(table) + "]");
                fail(key.source(), msg + did_you_mean_or_choices(key.str(), valid));
            }
            check_kind(*spec, value);
            if (spec->kind == Kind::table)
                check_table(*value.as_table(), table.empty() ? key.str() : std::string(table) + "." + std::string(key.str()));
        }
    }

    void check_kind(const Spec& spec, const toml::node& value) const {
        const std::string what = display(spec.table, spec.key) + " = " + case_reading::show(value) + ": ";
        if (spec.kind == Kind::table && !value.is_table())
            fail(value.source(), what + "expected a table, written [" +
                                     (spec.table.empty() ? "" : std::string(spec.table) + ".") +
                                     std::string(spec.key) + "] followed by its keys");
        if (spec.kind == Kind::text && !value.is_string()) fail(value.source(), what + "expected a string in quotes");
        if (spec.kind == Kind::integer && !value.is_integer())
            fail(value.source(), what + "expected a whole number (no decimal point, no quotes)");
        if (spec.kind == Kind::quantity && !value.is_number() && !value.is_string())
            fail(value.source(), what + "expected " + hint(spec));
    }

    static std::string hint(const Spec& s) {
        if (s.dimension == Dimension::dimensionless) return "a plain number";
        const std::string name = s.what.empty() ? std::string("a ") + dimension_name(s.dimension) : std::string(s.what);
        return name + ": a plain number in " + si_unit(s.dimension) + " or a string with a unit (" +
               accepted_units(s.dimension) + ")";
    }

    const toml::table& sub(const toml::table& t, std::string_view key) const {
        const toml::table* s = t[key].as_table();
        return s ? *s : empty_;
    }

    std::optional<std::string> text(const toml::table& t, std::string_view table, std::string_view key) const {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        return std::string(*n->value<std::string_view>());
    }

    std::optional<double> quantity(const toml::table& t, std::string_view table, std::string_view key) const {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        const Spec& spec = *find_spec(table, key);
        const std::string what = display(table, key) + " = " + case_reading::show(*n) + ": ";
        double v = 0;
        if (n->is_number()) {
            v = *n->value<double>();
        } else {
            try {
                v = parse_quantity(*n->value<std::string_view>(), spec.dimension);
            } catch (const std::invalid_argument& e) {
                fail(n->source(), what + e.what() + "; expected " + hint(spec));
            }
        }
        check_range(spec, v, *n, what);
        return v;
    }

    void check_range(const Spec& spec, double v, const toml::node& n, const std::string& what) const {
        const bool low = spec.min_exclusive ? !(v > spec.min) : !(v >= spec.min);
        if (!low && v <= spec.max) return;
        const std::string unit = spec.dimension == Dimension::dimensionless ? "" : std::string(" ") + si_unit(spec.dimension);
        std::string range = (spec.min_exclusive ? "> " : ">= ") + significant(spec.min, 6) + unit;
        if (spec.max < kInf) range += " and <= " + significant(spec.max, 6) + unit;
        fail(n.source(), what + "out of range; expected a value " + range);
    }

    std::optional<int> integer(const toml::table& t, std::string_view table, std::string_view key) const {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        const Spec& spec = *find_spec(table, key);
        const auto v = *n->value<int64_t>();
        if (v < spec.min || v > spec.max)
            fail(n->source(), display(table, key) + " = " + case_reading::show(*n) +
                                  ": out of range; expected a whole number from " +
                                  significant(spec.min, 6) + " to " + significant(spec.max, 6));
        return static_cast<int>(v);
    }

    // A default in use, listed in the results when it is physics (paper or assumed).
    void note_default(std::string_view table, std::string_view key, const std::string& value) {
        const Spec& spec = *find_spec(table, key);
        if (!spec.origin.empty()) defaults_.push_back(display(table, key) + " = " + value + " (" + std::string(spec.origin) + ")");
    }
    void take(const toml::table& t, std::string_view table, std::string_view key, double& field) {
        if (const auto v = quantity(t, table, key)) field = *v;
        else note_default(table, key, format_quantity(field, find_spec(table, key)->dimension));
    }
    void take(const toml::table& t, std::string_view table, std::string_view key, int& field) {
        if (const auto v = integer(t, table, key)) field = *v;
        else note_default(table, key, std::to_string(field));
    }

    std::string material(const toml::table& t, std::string_view table, std::string_view key,
                         const std::string& fallback) {
        const auto name = text(t, table, key);
        if (!name) {
            note_default(table, key, "\"" + fallback + "\"");
            return fallback;
        }
        if (!find_library_material(*name)) {
            std::vector<std::string_view> names;
            for (const auto& m : material_library()) names.push_back(m.name);
            fail(t.get(key)->source(), display(table, key) + " = \"" + *name +
                                           "\": no such library material; expected one of " + join(names));
        }
        return *name;
    }

    // One of `choices` (their index), or nothing when the key is absent.
    std::optional<int> choice(const toml::table& t, std::string_view table, std::string_view key,
                              const std::vector<std::string_view>& choices) const {
        const auto value = text(t, table, key);
        if (!value) return std::nullopt;
        for (size_t i = 0; i < choices.size(); ++i)
            if (*value == choices[i]) return static_cast<int>(i);
        fail(t.get(key)->source(), display(table, key) + " = \"" + *value + "\": expected one of " + join(choices));
    }

    void read_drums(const toml::table& t, WinderDrums& d) {
        constexpr std::string_view tb = "winder.drums";
        take(t, tb, "outer_diameter", d.outer_diameter);
        take(t, tb, "wall", d.wall);
        take(t, tb, "length", d.length);
        take(t, tb, "gap", d.gap);
        d.material = material(t, tb, "material", d.material);
        take(t, tb, "bearing_stiffness", d.bearing_stiffness_vertical);
        d.bearing_stiffness_horizontal = d.bearing_stiffness_vertical;
        if (const auto h = quantity(t, tb, "bearing_stiffness_horizontal")) d.bearing_stiffness_horizontal = *h;
        d.line_load = quantity(t, tb, "line_load");
        take(t, tb, "elements", d.elements);
        check_wall(t, tb, d.wall, d.outer_diameter);
    }

    // A tube's wall must leave a bore.
    void check_wall(const toml::table& t, std::string_view table, double wall, double outer_diameter) const {
        if (wall < outer_diameter / 2) return;
        fail(t.get("wall") ? t.get("wall")->source() : t.source(),
             display(table, "wall") + " = " + significant(wall) + " m must be less than half the outer diameter (" +
                 significant(outer_diameter) + " m)");
    }

    void read_rolls(const toml::table& t, WinderRolls& r) {
        constexpr std::string_view tb = "winder.rolls";
        take(t, tb, "count", r.count);
        take(t, tb, "width", r.width);
        take(t, tb, "gap", r.gap);
        take(t, tb, "core_inner_diameter", r.core_inner_diameter);
        take(t, tb, "core_outer_diameter", r.core_outer_diameter);
        r.core_material = material(t, tb, "core_material", r.core_material);
        r.paper_material = material(t, tb, "paper_material", r.paper_material);
        take(t, tb, "paper_density", r.paper_density);
        take(t, tb, "radial_modulus", r.radial_modulus);
        take(t, tb, "poisson", r.poisson);
        if (auto m = choice(t, tb, "model", {"rigid", "beam"})) r.model = static_cast<RollModel>(*m);
        take(t, tb, "diameter_start", r.diameter_start);
        take(t, tb, "diameter_end", r.diameter_end);
        check_rolls(t, r);
    }

    void check_rolls(const toml::table& t, const WinderRolls& r) const {
        const auto at = [&](std::string_view key) { return t.get(key) ? t.get(key)->source() : t.source(); };
        if (!(r.core_inner_diameter < r.core_outer_diameter))
            fail(at("core_inner_diameter"), "[winder.rolls] core_inner_diameter = " + significant(r.core_inner_diameter) +
                                                " m must be less than core_outer_diameter = " +
                                                significant(r.core_outer_diameter) + " m");
        if (!(r.diameter_start >= r.core_outer_diameter))
            fail(at("diameter_start"), "[winder.rolls] diameter_start = " + significant(r.diameter_start) +
                                           " m is smaller than the core (core_outer_diameter = " +
                                           significant(r.core_outer_diameter) +
                                           " m); expected a roll diameter at least the core's");
        if (!(r.diameter_end > r.diameter_start))
            fail(at("diameter_end"), "[winder.rolls] diameter_end = " + significant(r.diameter_end) +
                                         " m must be larger than diameter_start = " + significant(r.diameter_start) + " m");
    }

    void read_rider(const toml::table& t, WinderRider& r) {
        constexpr std::string_view tb = "winder.rider";
        take(t, tb, "outer_diameter", r.outer_diameter);
        take(t, tb, "wall", r.wall);
        take(t, tb, "length", r.length);
        r.material = material(t, tb, "material", r.material);
        take(t, tb, "support_stiffness", r.support_stiffness);
        take(t, tb, "line_load", r.line_load);
        take(t, tb, "elements", r.elements);
        check_wall(t, tb, r.wall, r.outer_diameter);
    }

    void read_damping(const toml::table& t, WinderDamping& d) {
        take(t, "winder.damping", "drums", d.drums);
        take(t, "winder.damping", "nips", d.nips);
        take(t, "winder.damping", "rider", d.rider);
    }

    void read_sweep(const toml::table& t, WinderSweep& s) {
        constexpr std::string_view tb = "winder.sweep";
        take(t, tb, "points", s.points);
        take(t, tb, "harmonics", s.harmonics);
        take(t, tb, "max_frequency", s.max_frequency);
        if (auto c = choice(t, tb, "response_drum", {"front", "rear"})) s.response_drum = static_cast<DrumSide>(*c);
        if (auto c = choice(t, tb, "response_direction", {"vertical", "horizontal"}))
            s.response_direction = static_cast<ResponseDirection>(*c);
    }

    // Checks that join tables: the rolls fit on the drums and under the rider,
    // and the smallest roll does not fall between the drums.
    void check_geometry(const toml::table& winder, const WinderScene& s) const {
        const double row = s.rolls.count * s.rolls.width + (s.rolls.count - 1) * s.rolls.gap;
        const toml::table& rolls = sub(winder, "rolls");
        const toml::source_region& at = rolls.source().begin.line ? rolls.source() : winder.source();
        const std::string row_text = "the row of rolls (" + std::to_string(s.rolls.count) + " x " +
                                     significant(s.rolls.width) + " m with " + significant(s.rolls.gap) +
                                     " m gaps = " + significant(row) + " m)";
        if (row > s.drums.length)
            fail(at, row_text + " is longer than [winder.drums] length = " + significant(s.drums.length) +
                         " m; expected the rolls to fit on the drums");
        if (row > s.rider.length)
            fail(at, row_text + " is longer than [winder.rider] length = " + significant(s.rider.length) +
                         " m; expected the rider to cover every roll");
        if (!(s.rolls.diameter_start > s.drums.gap))
            fail(at, "[winder.rolls] diameter_start = " + significant(s.rolls.diameter_start) +
                         " m is not larger than the gap between the drums ([winder.drums] gap = " +
                         significant(s.drums.gap) + " m): the roll would fall between them");
    }
};

}  // namespace

WinderScene read_winder_text(std::string_view text, const std::string& path) {
    const toml::table root = parse_toml_input(text, path, "a valid TOML winder file (docs/how-to/winder.md)");
    try {
        return WinderReader(path).read(root);
    } catch (const InputError& e) {  // a key echoed in a message: the user's characters
        throw InputError(restore_characters(e.what()));
    }
}

WinderScene read_winder_file(const std::string& path) {
    return read_winder_text(read_input_file(path, "winder file"), path);
}

OrthotropicMaterial winder_material(const std::string& library_name) {
    const LibraryMaterial* m = find_library_material(library_name);
    COREMODAL_ASSERT(m != nullptr);  // checked when the file was read
    return to_material(*m);
}

const char* roll_model_name(RollModel m) { return m == RollModel::rigid ? "rigid" : "beam"; }
const char* drum_side_name(DrumSide s) { return s == DrumSide::front ? "front" : "rear"; }
const char* direction_name(ResponseDirection d) { return d == ResponseDirection::vertical ? "vertical" : "horizontal"; }

namespace {
// The string values a key takes (the reader's `choice` calls); none for the others.
std::vector<std::string> winder_choices(std::string_view table, std::string_view key) {
    if (table == "winder.rolls" && key == "model") return {"rigid", "beam"};
    if (key == "response_drum") return {"front", "rear"};
    if (key == "response_direction") return {"vertical", "horizontal"};
    return {};
}
}  // namespace

std::string winder_json_schema() {
    using Json = nlohmann::ordered_json;
    // One schema object per table of the key table, filled key by key.
    std::map<std::string, Json, std::less<>> tables;
    const auto table_of = [&](std::string_view name) -> Json& {
        auto [at, added] = tables.try_emplace(std::string(name));
        if (added) at->second = Json{{"type", "object"}, {"additionalProperties", false}, {"properties", Json::object()}};
        return at->second;
    };
    for (const Spec& s : schema()) {
        Json value;
        switch (s.kind) {
        case Kind::table: value = Json{{"$ref", "#/definitions/" + std::string(s.table.empty() ? "" : std::string(s.table) + ".") + std::string(s.key)}}; break;
        case Kind::text: {
            const auto choices = winder_choices(s.table, s.key);
            value = choices.empty() ? Json{{"type", "string"}} : Json{{"enum", choices}};
            break;
        }
        case Kind::integer: value = Json{{"type", "integer"}, {"minimum", s.min}, {"maximum", s.max}}; break;
        case Kind::quantity: {
            Json number{{"type", "number"}};
            if (std::isfinite(s.min)) number[s.min_exclusive ? "exclusiveMinimum" : "minimum"] = s.min;
            if (std::isfinite(s.max)) number["maximum"] = s.max;
            value = Json{{"anyOf", Json::array({number, Json{{"type", "string"}, {"pattern", quantity_pattern(s.dimension, false)}}})}};
            break;
        }
        }
        const std::string unit = s.kind == Kind::quantity && s.dimension != Dimension::dimensionless
                                     ? std::string(" (plain numbers in ") + si_unit(s.dimension) + ")"
                                     : "";
        const std::string description = (s.origin.empty() ? "" : std::string(s.origin) + " default") + unit;
        if (!description.empty()) value["description"] = description;
        table_of(s.table)["properties"][std::string(s.key)] = value;
    }
    Json root = table_of("");
    root["$schema"] = kJsonSchemaDraft;
    root["title"] = "coremodal two-drum winder case file ([winder], docs/how-to/winder.md)";
    root["required"] = Json::array({"winder"});
    Json definitions = Json::object();
    for (const auto& [name, table] : tables)
        if (!name.empty()) definitions[name] = table;
    root["definitions"] = definitions;
    return root.dump(2) + "\n";
}

}  // namespace coremodal
