#include "selection/selection_scene.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "common/join.hpp"
#include "scene/case_json_schema.hpp"
#include "scene/case_key_ranges.hpp"
#include "scene/case_reader.hpp"  // case_reading::show
#include "scene/case_schema.hpp"  // did_you_mean_or_choices
#include "scene/toml_text.hpp"
#include "scene/units.hpp"

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>

namespace coremodal {
namespace {

// Hard limits that catch unit slips (a plain 76 is 76 m, not 76 mm), not physics.
constexpr double kMaxWidth = 20.0;    // m
constexpr double kMaxChuck = 2.0;     // m: a chuck's supporting length (rotogravure's longest: 340 mm)

const std::vector<std::string_view> kTopKeys = {"name", "description", "selection"};
const std::vector<std::string_view> kSelectionKeys = {"failure_probability", "confidence",         "cycles",
                                                      "paper_density",       "rest_paper_modulus",
                                                      "rest_paper_density",  "core",               "stand",
                                                      "reel"};
const std::vector<std::string_view> kCoreKeys = {"name",    "inner_diameter", "outer_diameter", "flexural_modulus",
                                                 "density", "price_per_m",    "durability",     "b0",
                                                 "b1",      "s_log",          "test_chuck_length"};
const std::vector<std::string_view> kStandKeys = {"name",         "chuck_length", "li",
                                                  "chuck_factor", "web_speed",    "safe_factor",
                                                  "winder",       "centre_winder_factor", "chuck_length_exponent",
                                                  "rest_roll_diameter", "roll_diameter", "cores",
                                                  "amplitude_limit"};
const std::vector<std::string_view> kReelKeys = {"stand", "width", "diameter", "web_speed"};

class SelectionReader {
public:
    explicit SelectionReader(std::string path) : path_(std::move(path)) {}

    SelectionScene read(const toml::table& root) {
        SelectionScene s;
        s.source = path_;
        check_keys(root, "the top level", kTopKeys);
        s.name = text(root, "", "name").value_or(std::filesystem::path(path_).stem().string());
        s.description = text(root, "", "description").value_or("");
        const toml::table* sel = root["selection"].as_table();
        if (!sel) fail(root.source(), "no [selection] table; expected a core-selection file (docs/how-to/durability.md)");
        check_keys(*sel, "[selection]", kSelectionKeys);
        const std::string t = "selection";
        take(*sel, t, "failure_probability", Dimension::dimensionless, 0, 0.5, s.failure_probability,
             "Figs. 18-19: of order 1e-5");
        take(*sel, t, "confidence", Dimension::dimensionless, 0.5, 1, s.confidence, "{23}, {26}: for example 99 %");
        if (s.confidence >= 1) fail(sel->get("confidence")->source(), "[selection] confidence must be below 1");
        take(*sel, t, "cycles", Dimension::dimensionless, 0.5 - 1e-12, 1e9, s.cycles,
             "one winding and one unwinding, Fig. 13");
        s.paper_density = required(*sel, t, "paper_density", Dimension::density, 0, 3000);
        s.rest_paper_modulus = required(*sel, t, "rest_paper_modulus", Dimension::pressure, 0, 1e11);
        s.rest_paper_density = required(*sel, t, "rest_paper_density", Dimension::density, 0, 3000);
        for (const toml::table* c : tables(*sel, "core")) s.cores.push_back(read_core(*c));
        for (const toml::table* st : tables(*sel, "stand")) s.stands.push_back(read_stand(*st));
        for (const toml::table* r : tables(*sel, "reel")) s.reels.push_back(read_reel(*r, s));
        if (s.cores.empty()) fail(sel->source(), "[selection] has no [[selection.core]]; expected one per core grade");
        if (s.stands.empty()) fail(sel->source(), "[selection] has no [[selection.stand]]; expected at least one");
        for (const Stand& st : s.stands)
            check_stand_cores(st, s.cores, *stand_nodes_.at(&st - s.stands.data()));
        for (const Stand& st : s.stands)
            for (const CoreGrade& c : s.cores)
                if (st.takes(c.name) && st.roll_diameter <= c.outer_diameter)
                    fail(stand_nodes_.at(&st - s.stands.data())->source(),
                         "[[selection.stand]] " + st.name + ": roll_diameter = " + mm(st.roll_diameter) +
                             " must be larger than core " + c.name + "'s outer_diameter = " + mm(c.outer_diameter));
        for (const Stand& st : s.stands)
            for (const CoreGrade& c : s.cores)
                if (st.takes(c.name) && st.rest_roll_diameter < c.outer_diameter)
                    fail(stand_nodes_.at(&st - s.stands.data())->source(),
                         "[[selection.stand]] " + st.name + ": rest_roll_diameter = " + mm(st.rest_roll_diameter) +
                             " is smaller than core " + c.name + "'s outer_diameter = " + mm(c.outer_diameter));
        s.defaults = std::move(defaults_);
        return s;
    }

private:
    std::string path_;
    std::vector<std::string> defaults_;
    std::vector<const toml::table*> stand_nodes_;

    static std::string mm(double m) { return significant(m * 1e3, 5) + " mm"; }

    [[noreturn]] void fail(const toml::source_region& where, const std::string& what) const {
        const std::string at = where.begin.line == 0 ? path_ + ": "
                                                     : path_ + ":" + std::to_string(where.begin.line) + ":" +
                                                           std::to_string(where.begin.column) + ": ";
        throw InputError(at + what);
    }

    void check_keys(const toml::table& t, const std::string& where, const std::vector<std::string_view>& keys) const {
        for (const auto& [key, value] : t)
            if (std::find(keys.begin(), keys.end(), key.str()) == keys.end())
                fail(key.source(), "unknown key '" + std::string(key.str()) + "' in " + where +
                                       did_you_mean_or_choices(key.str(), keys));
    }

    std::vector<const toml::table*> tables(const toml::table& t, std::string_view key) const {
        std::vector<const toml::table*> out;
        const toml::node* n = t.get(key);
        if (!n) return out;
        const toml::array* a = n->as_array();
        if (!a || !a->is_array_of_tables())
            fail(n->source(), "[selection] " + std::string(key) + ": expected tables written [[selection." +
                                  std::string(key) + "]]");
        for (const toml::node& e : *a) out.push_back(e.as_table());
        return out;
    }

    std::optional<std::string> text(const toml::table& t, const std::string& table, std::string_view key) const {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        if (!n->is_string())
            fail(n->source(), label(table, key) + " = " + case_reading::show(*n) + ": expected a string in quotes");
        return std::string(*n->value<std::string_view>());
    }

    static std::string label(const std::string& table, std::string_view key) {
        return (table.empty() ? "" : "[" + table + "] ") + std::string(key);
    }

    // A quantity in (min, max] (min inclusive when a dimensionless count asks).
    std::optional<double> quantity(const toml::table& t, const std::string& table, std::string_view key, Dimension d,
                                   double min, double max) const {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        const std::string what = label(table, key) + " = " + case_reading::show(*n) + ": ";
        double v = 0;
        if (n->is_number()) {
            v = *n->value<double>();
        } else if (n->is_string()) {
            try {
                v = parse_quantity(*n->value<std::string_view>(), d);
            } catch (const std::invalid_argument& e) {
                fail(n->source(), what + e.what());
            }
        } else {
            fail(n->source(), what + "expected a " + dimension_name(d) + " (a number in " + si_unit(d) +
                                  " or a string with its unit)");
        }
        if (!std::isfinite(v) || !(v > min) || v > max)
            fail(n->source(), what + "out of range; expected a value > " + significant(min, 6) + " and <= " +
                                  significant(max, 6) + (d == Dimension::dimensionless ? "" : std::string(" ") + si_unit(d)));
        return v;
    }

    double required(const toml::table& t, const std::string& table, std::string_view key, Dimension d, double min,
                    double max) const {
        if (const auto v = quantity(t, table, key, d, min, max)) return *v;
        fail(t.source(), label(table, key) + " is missing; expected a " + dimension_name(d) + " such as " +
                             (d == Dimension::length ? "\"150 mm\"" : d == Dimension::density ? "\"920 kg/m^3\""
                              : d == Dimension::pressure ? "\"6.5 GPa\"" : d == Dimension::speed ? "\"15 m/s\"" : "0.85"));
    }

    void take(const toml::table& t, const std::string& table, std::string_view key, Dimension d, double min,
              double max, double& field, const std::string& source) {
        if (const auto v = quantity(t, table, key, d, min, max)) field = *v;
        else defaults_.push_back(label(table, key) + " = " + significant(field, 6) +
                                 (d == Dimension::dimensionless ? "" : std::string(" ") + si_unit(d)) + " (Ilomäki, " +
                                 source + ")");
    }

    CoreGrade read_core(const toml::table& c) {
        check_keys(c, "[[selection.core]]", kCoreKeys);
        CoreGrade g;
        const std::string t = "selection.core";
        g.name = text(c, t, "name").value_or("");
        if (g.name.empty()) fail(c.source(), "[[selection.core]] has no name; expected name = \"A\"");
        const std::string at = "selection.core " + g.name;
        g.inner_diameter = required(c, at, "inner_diameter", Dimension::length, 0, key_ranges::kMaxDiameter);
        g.outer_diameter = required(c, at, "outer_diameter", Dimension::length, 0, key_ranges::kMaxDiameter);
        if (g.outer_diameter <= g.inner_diameter)
            fail(c.get("outer_diameter")->source(), "[" + at + "] outer_diameter = " + mm(g.outer_diameter) +
                                                        " must be larger than inner_diameter = " + mm(g.inner_diameter));
        g.flexural_modulus = required(c, at, "flexural_modulus", Dimension::pressure, 0, 1e11);
        g.density = required(c, at, "density", Dimension::density, 0, 3000);
        g.price_per_m = quantity(c, at, "price_per_m", Dimension::dimensionless, 0, 1e9);
        if (const auto file = text(c, at, "durability")) {
            for (std::string_view k : {"b0", "b1", "s_log", "test_chuck_length"})
                if (c.get(k))
                    fail(c.get(k)->source(), "[" + at + "] " + std::string(k) +
                                                 ": give either durability = \"file.csv\" or b0, b1, s_log and "
                                                 "test_chuck_length, not both");
            const std::filesystem::path p = std::filesystem::path(path_).parent_path() / *file;
            g.data_file = p.string();
            g.data = read_durability_data(g.data_file);
            g.test_chuck_length = g.data->chuck_length_m;
            return g;
        }
        const toml::node* b0 = c.get("b0");
        if (!b0)
            fail(c.source(), "[" + at + "] has no durability; expected durability = \"file.csv\" (the simulator "
                             "results) or b0 = \"28 kN\", b1, s_log and test_chuck_length of a fit");
        g.b0_newton = weight(*b0, at);
        g.b1 = required(c, at, "b1", Dimension::dimensionless, -10, 10);
        g.s_log = required(c, at, "s_log", Dimension::dimensionless, 0, 2);
        g.test_chuck_length = required(c, at, "test_chuck_length", Dimension::length, 0, kMaxWidth);
        return g;
    }

    void check_stand_cores(const Stand& st, const std::vector<CoreGrade>& cores, const toml::table& t) const {
        std::vector<std::string_view> names;
        for (const CoreGrade& c : cores) names.push_back(c.name);
        for (const std::string& c : st.cores)
            if (std::find(names.begin(), names.end(), c) == names.end())
                fail(t.get("cores")->source(), "[selection.stand " + st.name + "] cores: \"" + c +
                                                   "\" is not a [[selection.core]] name; expected some of " +
                                                   join(names));
    }

    double weight(const toml::node& n, const std::string& at) const {
        const std::string what = "[" + at + "] b0 = " + case_reading::show(n) + ": ";
        if (!n.is_string()) fail(n.source(), what + "expected a weight with its unit, e.g. \"28 kN\" (N, kN, kg, t)");
        const std::string s(*n.value<std::string_view>());
        const auto space = s.find(' ');
        double v = 0;
        double unit = space == std::string::npos ? 0 : weight_unit_in_newton(s.substr(space + 1));
        try {
            v = std::stod(s.substr(0, space));
        } catch (const std::exception&) {
            unit = 0;
        }
        if (unit == 0 || !(v > 0) || !std::isfinite(v))
            fail(n.source(), what + "expected a positive weight with its unit, e.g. \"28 kN\" (N, kN, kg, t)");
        return v * unit;
    }

    Stand read_stand(const toml::table& st) {
        check_keys(st, "[[selection.stand]]", kStandKeys);
        stand_nodes_.push_back(&st);
        Stand s;
        s.name = text(st, "selection.stand", "name").value_or("");
        if (s.name.empty()) fail(st.source(), "[[selection.stand]] has no name; expected name = \"news\"");
        const std::string at = "selection.stand " + s.name;
        s.chuck_length = required(st, at, "chuck_length", Dimension::length, 0, kMaxChuck);
        s.li = s.chuck_length / 2;
        if (const auto li = quantity(st, at, "li", Dimension::length, 0, kMaxChuck)) s.li = *li;
        else defaults_.push_back("[" + at + "] li = " + mm(s.li) + " (assumed: the middle of the chuck)");
        s.chuck_factor = required(st, at, "chuck_factor", Dimension::dimensionless, 0, 1);
        take(st, at, "web_speed", Dimension::speed, 0, key_ranges::kMaxWebSpeed, s.web_speed, "Figs. 18-19: 15 m/s");
        take(st, at, "safe_factor", Dimension::dimensionless, 0, 1, s.safe_factor,
             "I-5: 0.7 without a safety cage, keeps about +-5 mm");
        take(st, at, "amplitude_limit", Dimension::length, 0, 0.1, s.amplitude_limit,
             "Figs. 18-19: +-5 mm mid-span");
        if (const auto w = text(st, at, "winder")) {
            if (*w != "two-drum" && *w != "centre")
                fail(st.get("winder")->source(), "[" + at + "] winder = \"" + *w + "\": expected \"two-drum\" or \"centre\"");
            s.winder = *w;
        } else {
            defaults_.push_back("[" + at + "] winder = \"two-drum\" (assumed)");
        }
        if (s.winder == "centre" || st.get("centre_winder_factor"))
            take(st, at, "centre_winder_factor", Dimension::dimensionless, 0, 1, s.centre_winder_factor,
                 "a centre winder: maximum roll weight decreased 20 %");
        take(st, at, "chuck_length_exponent", Dimension::dimensionless, -1e-12, 2, s.chuck_length_exponent,
             "doubling the supporting length can double the roll mass");
        s.rest_roll_diameter = required(st, at, "rest_roll_diameter", Dimension::length, 0, key_ranges::kMaxDiameter);
        s.roll_diameter = required(st, at, "roll_diameter", Dimension::length, 0, key_ranges::kMaxDiameter);
        if (const toml::node* n = st.get("cores")) {
            const toml::array* a = n->as_array();
            if (!a || a->empty() || !a->is_homogeneous(toml::node_type::string))
                fail(n->source(), "[" + at + "] cores = " + case_reading::show(*n) +
                                      ": expected the names of the grades its chucks take, e.g. [\"A\", \"B\"]");
            for (const toml::node& e : *a) s.cores.emplace_back(*e.value<std::string_view>());
        }
        return s;
    }

    Reel read_reel(const toml::table& r, const SelectionScene& s) {
        check_keys(r, "[[selection.reel]]", kReelKeys);
        Reel reel;
        reel.stand = text(r, "selection.reel", "stand").value_or("");
        std::vector<std::string_view> names;
        for (const Stand& st : s.stands) names.push_back(st.name);
        if (std::find(names.begin(), names.end(), reel.stand) == names.end())
            fail(r.get("stand") ? r.get("stand")->source() : r.source(),
                 "[[selection.reel]] stand = \"" + reel.stand + "\": expected the name of a [[selection.stand]]: " +
                     join(names));
        reel.width = required(r, "selection.reel", "width", Dimension::length, 0, kMaxWidth);
        reel.diameter = required(r, "selection.reel", "diameter", Dimension::length, 0, key_ranges::kMaxDiameter);
        reel.web_speed = quantity(r, "selection.reel", "web_speed", Dimension::speed, 0, key_ranges::kMaxWebSpeed);
        const Stand& st = *std::find_if(s.stands.begin(), s.stands.end(),
                                        [&](const Stand& x) { return x.name == reel.stand; });
        for (const CoreGrade& c : s.cores)
            if (st.takes(c.name) && reel.diameter <= c.outer_diameter)
                fail(r.get("diameter")->source(), "[[selection.reel]] diameter = " + mm(reel.diameter) +
                                                      " must be larger than core " + c.name +
                                                      "'s outer_diameter = " + mm(c.outer_diameter));
        // Both chucks inside the core, and I-7's free span between their li.
        const double held = 2 * std::max(st.li, st.chuck_length);
        if (reel.width <= held)
            fail(r.get("width")->source(), "[[selection.reel]] width = " + mm(reel.width) + " leaves no free span "
                                           "between the chucks of stand " + st.name + " (2 x max(li, chuck_length) = " +
                                           mm(held) + "); expected a wider reel");
        return reel;
    }
};

using SchemaJson = nlohmann::ordered_json;

// The schema of every key of a selection file by name, as the reader takes it.
std::map<std::string_view, SchemaJson> selection_key_types() {
    using Json = SchemaJson;
    // A quantity as the reader takes it: a plain number in SI within
    // (min, max], or a string with a unit of its dimension.
    const auto quantity = [](Dimension d, double min, double max) {
        Json number{{"type", "number"}, {"exclusiveMinimum", min}, {"maximum", max}};
        Json out{{"anyOf", Json::array({number, Json{{"type", "string"}, {"pattern", quantity_pattern(d, false)}}})}};
        if (d != Dimension::dimensionless) out["description"] = std::string("plain numbers in ") + si_unit(d);
        return out;
    };
    const Json text{{"type", "string"}};
    const Json length = quantity(Dimension::length, 0, key_ranges::kMaxDiameter);
    const Json modulus = quantity(Dimension::pressure, 0, 1e11);
    const Json density = quantity(Dimension::density, 0, 3000);
    const Json speed = quantity(Dimension::speed, 0, key_ranges::kMaxWebSpeed);
    const Json share = quantity(Dimension::dimensionless, 0, 1);
    const Json weight{{"type", "string"},
                      {"pattern", R"(^[+]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)? (N|kN|kg|t)$)"},
                      {"description", "a weight with its unit: N, kN, kg or t, e.g. \"28 kN\""}};
    return {
        {"name", text},
        {"description", text},
        {"failure_probability", quantity(Dimension::dimensionless, 0, 0.5)},
        {"confidence", quantity(Dimension::dimensionless, 0.5, 1)},
        {"cycles", quantity(Dimension::dimensionless, 0.5 - 1e-12, 1e9)},
        {"paper_density", density},
        {"rest_paper_modulus", modulus},
        {"rest_paper_density", density},
        {"inner_diameter", length},
        {"outer_diameter", length},
        {"flexural_modulus", modulus},
        {"density", density},
        {"price_per_m", quantity(Dimension::dimensionless, 0, 1e9)},
        {"durability", Json{{"type", "string"}, {"description", "simulator results (CSV), relative to this file"}}},
        {"b0", weight},
        {"b1", quantity(Dimension::dimensionless, -10, 10)},
        {"s_log", quantity(Dimension::dimensionless, 0, 2)},
        {"test_chuck_length", quantity(Dimension::length, 0, kMaxWidth)},
        {"chuck_length", quantity(Dimension::length, 0, kMaxChuck)},
        {"li", quantity(Dimension::length, 0, kMaxChuck)},
        {"chuck_factor", share},
        {"web_speed", speed},
        {"safe_factor", share},
        {"winder", Json{{"enum", Json::array({"two-drum", "centre"})}}},
        {"centre_winder_factor", share},
        {"chuck_length_exponent", quantity(Dimension::dimensionless, -1e-12, 2)},
        {"amplitude_limit", quantity(Dimension::length, 0, 0.1)},
        {"rest_roll_diameter", length},
        {"roll_diameter", length},
        {"cores", Json{{"type", "array"}, {"minItems", 1}, {"items", text}}},
        {"stand", text},
        {"width", quantity(Dimension::length, 0, kMaxWidth)},
        {"diameter", length},
    };
}

}  // namespace

std::string selection_json_schema() {
    using Json = SchemaJson;
    const std::map<std::string_view, Json> types = selection_key_types();
    // A table of the reader's keys (its key lists above), so that the schema
    // and the reader cannot disagree on which keys exist.
    const auto table = [&](const std::vector<std::string_view>& keys, std::vector<std::string> required,
                           std::map<std::string_view, Json> own = {}) {
        Json properties = Json::object();
        for (std::string_view k : keys) {
            const auto& where = own.count(k) ? own : types;
            if (!where.count(k)) throw std::logic_error("selection_json_schema: no type for key " + std::string(k));
            properties[std::string(k)] = where.at(k);
        }
        return Json{{"type", "object"}, {"additionalProperties", false}, {"required", required}, {"properties", properties}};
    };
    const auto list_of = [](const Json& item, int min_items) {
        return Json{{"type", "array"}, {"minItems", min_items}, {"items", item}};
    };
    Json core = table(kCoreKeys, {"name", "inner_diameter", "outer_diameter", "flexural_modulus", "density"});
    // The durability: a data file, or the four numbers of a fit made elsewhere, not both.
    core["oneOf"] = Json::array({Json{{"required", Json::array({"durability"})}},
                                 Json{{"required", Json::array({"b0", "b1", "s_log", "test_chuck_length"})}}});
    const Json selection = table(kSelectionKeys, {"paper_density", "rest_paper_modulus", "rest_paper_density", "core", "stand"},
                                 {{"core", list_of(core, 1)},
                                  {"stand", list_of(table(kStandKeys, {"name", "chuck_length", "chuck_factor",
                                                                      "rest_roll_diameter", "roll_diameter"}), 1)},
                                  {"reel", list_of(table(kReelKeys, {"stand", "width", "diameter"}), 0)}});
    Json root = table(kTopKeys, {"selection"}, {{"selection", selection}});
    root["$schema"] = kJsonSchemaDraft;
    root["title"] = "coremodal core-selection file ([selection], docs/how-to/durability.md)";
    return root.dump(2) + "\n";
}

SelectionScene read_selection_text(const std::string& text, const std::string& path) {
    const toml::table root = parse_toml_input(text, path, "a valid TOML core-selection file (docs/how-to/durability.md)");
    try {
        return SelectionReader(path).read(root);
    } catch (const InputError& e) {
        throw InputError(restore_characters(e.what()));
    }
}

SelectionScene read_selection_file(const std::string& path) {
    return read_selection_text(read_input_file(path, "core-selection file"), path);
}

}  // namespace coremodal
