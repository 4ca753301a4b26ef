// The [study] / [calibration] table read and checked (scene/case_sweep_impl.hpp):
// its options, its parameters, every key path against the case schema and
// every value's type, unit and range.
#include "scene/case_sweep_impl.hpp"

#include "common/error.hpp"
#include "common/join.hpp"
#include "scene/case_reader.hpp"
#include "scene/case_schema.hpp"
#include "scene/case_table.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/toml_text.hpp"
#include "scene/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace coremodal::case_sweeping {
namespace {

// More points than this is a typo in a range, not a study anyone can run.
constexpr long kMaxSweepPoints = 100000;
// A range value this close to a whole number is one (integer keys).
constexpr double kWholeNumberTolerance = 1e-9;


std::string support_type_of(const toml::table& root) {
    return std::string(root["supports"]["type"].value_or<std::string_view>("free"));
}

// The unit range values are shown in: the one `from` was written in ("5 mm"
// gives labels "5 mm", "12.5 mm", ...), else SI.
struct RangeUnit {
    std::string name;  // "" = SI via format_quantity
    double factor = 1;
    Dimension dimension = Dimension::dimensionless;
    std::string label(double si) const {
        if (name.empty()) return format_quantity(si, dimension);
        char text[32];
        std::snprintf(text, sizeof text, "%.4g", si / factor);
        return std::string(text) + " " + name;
    }
};

RangeUnit range_unit(const toml::node& from, Dimension d) {
    RangeUnit u{"", 1, d};
    const std::optional<std::string_view> text = from.value<std::string_view>();
    if (!text || d == Dimension::dimensionless) return u;
    const size_t start = text->find_first_not_of("+-0123456789.eE ");
    if (start == std::string_view::npos) return u;
    const std::string name(text->substr(start));
    try {
        u.factor = parse_quantity("1 " + name, d);
        u.name = name;
    } catch (const std::invalid_argument&) {  // already refused with its own message
    }
    return u;
}

// Reads and checks the sweep table. Messages: FILE:LINE:COL: what; expected.
class SweepReader {
public:
    SweepReader(const std::string& path, std::string_view table) : path_(path), table_(table) {
        display_ = "[" + table_ + "]";
    }

    void read(const toml::table& root, CaseSweep::Impl& out, const std::optional<std::string>& mesh_override) {
        const toml::node* node = root.get(table_);
        if (!node)
            throw InputError(path_ + ": no " + display_ + " table; expected e.g.\n  " + display_ +
                             "\n  parameters = [{ key = \"core.length\", from = \"2 m\", to = \"4 m\", steps = 5 }]\n"
                             "(docs/" + (table_ == "study" ? "studies" : "calibration") + ".md)");
        const toml::table& t = *node->as_table();
        check_keys(t, table_, display_);
        read_options(root, t, out, mesh_override);
        read_parameters(root, t, out);
    }

    // One key path resolved for `fit` and `sensitivity` (resolve_key_path).
    std::pair<KeyPath, const KeySpec*> resolve_key(const toml::table& root, const std::string& text,
                                                   const toml::node& where, const std::string& display) const {
        return resolve(root, text, where, display);
    }

private:
    std::string path_, table_, display_;

    std::string location(const toml::source_region& where) const {
        if (where.begin.line == 0) return path_ + ": ";
        return path_ + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column) + ": ";
    }
    [[noreturn]] void fail(const toml::node& where, const std::string& what) const {
        throw InputError(location(where.source()) + what);
    }

    void check_keys(const toml::table& t, const std::string& schema, const std::string& display) const {
        for (const auto& [key, value] : t) {
            if (find_key(schema, key.str())) continue;
            const std::vector<std::string_view> valid = keys_of(schema);
            throw InputError(location(key.source()) + "unknown key '" + std::string(key.str()) + "' in " + display +
                             did_you_mean_or_choices(key.str(), valid));
        }
    }

    // A number (SI) or a string with a unit, range-checked against `spec`.
    double quantity(const toml::node& node, const KeySpec& spec, const std::string& what) const {
        double v = 0;
        if (node.is_number()) {
            v = *node.value<double>();
            if (!std::isfinite(v)) fail(node, what + ": expected a finite number");
        } else if (node.is_string()) {
            try {
                v = parse_quantity(*node.value<std::string_view>(), spec.dimension);
            } catch (const std::invalid_argument& e) {
                fail(node, what + ": " + e.what());
            }
        } else {
            fail(node, what + ": expected a number or a string with a unit, e.g. \"" +
                           std::string(spec.dimension == Dimension::length ? "10 mm" : "1") + "\"");
        }
        check_range(node, spec, v, what);
        return v;
    }

    // The case reader's own check and words (case_schema.hpp: out_of_range).
    void check_range(const toml::node& node, const KeySpec& spec, double v, const std::string& what) const {
        if (const std::optional<std::string> why = out_of_range(spec, v, node.is_number() ? case_reading::show(node) : ""))
            fail(node, what + " = " + format_quantity(v, spec.dimension) + " " + *why);
    }

    std::int64_t integer(const toml::node& node, const KeySpec& spec, const std::string& what) const {
        if (!node.is_integer()) fail(node, what + ": expected a whole number");
        const std::int64_t v = *node.value<std::int64_t>();
        if (const std::optional<std::string> why = integer_out_of_range(spec, v))
            fail(node, what + " = " + std::to_string(v) + " " + *why);
        return v;
    }

    // ---- options: mesh, modes, safe_factor, web_speed, holdout_every, max_error

    void read_options(const toml::table& root, const toml::table& t, CaseSweep::Impl& out,
                      const std::optional<std::string>& mesh_override) const {
        SweepOptions& o = out.options;
        // The case's own [analysis] modes or band stand unless the table says; a
        // case without them gets the sweep's default (few modes: fast points).
        const bool case_modes = root["analysis"]["modes"] || root["analysis"]["band"];
        if (!case_modes) o.modes = table_ == "study" ? kStudyDefaultModes : kCalibrationDefaultModes;
        const auto option = [&](std::string_view key) -> const toml::node* { return t.get(key); };
        const auto what = [&](std::string_view key) { return display_ + " " + std::string(key); };
        if (const toml::node* n = option("modes")) o.modes = static_cast<int>(integer(*n, *find_key(table_, "modes"), what("modes")));
        if (const toml::node* n = option("safe_factor"))
            o.safe_factor = quantity(*n, *find_key(table_, "safe_factor"), what("safe_factor"));
        if (const toml::node* n = option("web_speed"))
            o.web_speed_m_s = quantity(*n, *find_key(table_, "web_speed"), what("web_speed"));
        if (const toml::node* n = option("holdout_every"))
            o.holdout_every = static_cast<int>(integer(*n, *find_key(table_, "holdout_every"), what("holdout_every")));
        if (const toml::node* n = option("max_error"))
            o.max_error = quantity(*n, *find_key(table_, "max_error"), what("max_error"));
        read_mesh_option(root, option("mesh"), out, mesh_override);
    }

    // The mesh level of every point: --mesh, else the table's mesh, else the
    // case's own [mesh] if it has one, else kSweepDefaultMesh.
    void read_mesh_option(const toml::table& root, const toml::node* node, CaseSweep::Impl& out,
                          const std::optional<std::string>& mesh_override) const {
        std::vector<std::string_view> levels;
        for (const MeshLevel& l : kMeshLevels) levels.push_back(l.name);
        const auto check_level = [&](const std::string& level, const std::string& what, const toml::node* at) {
            if (find_mesh_level(level)) return;
            const std::string msg = what + " = \"" + level + "\": unknown mesh level; expected one of " + join(levels);
            if (at) fail(*at, msg);
            throw InputError(msg);
        };
        std::string level;
        std::string source;
        if (mesh_override) {
            level = *mesh_override, source = "--mesh";
            check_level(level, "--mesh", nullptr);
        } else if (node) {
            if (!node->is_string()) fail(*node, display_ + " mesh: expected a mesh level in quotes, e.g. mesh = \"coarse\"");
            level = std::string(*node->value<std::string_view>()), source = display_ + " mesh";
            check_level(level, display_ + " mesh", node);
        }
        const bool case_mesh = root.get("mesh") != nullptr;
        const bool mesh_file = root["mesh"]["file"].is_string();
        if (level.empty()) {
            if (case_mesh) return;  // the case's own [mesh]
            level = std::string(kSweepDefaultMesh);
        }
        if (mesh_file) {
            const std::string msg = source + " = \"" + level + "\" has no effect: the case uses [mesh] file; "
                                    "expected no mesh level for a case with its own mesh file";
            if (node && !mesh_override) fail(*node, msg);
            throw InputError(path_ + ": " + msg);
        }
        out.options.mesh_level = level;
        out.replace_mesh = true;
    }

    // ---- parameters -----------------------------------------------------

    void read_parameters(const toml::table& root, const toml::table& t, CaseSweep::Impl& out) const {
        const toml::node* node = t.get("parameters");
        if (!node)
            fail(t, display_ + " parameters is missing; expected e.g. parameters = [{ key = \"core.length\", "
                                "values = [\"2 m\", \"3 m\"] }]");
        const toml::array* items = node->as_array();
        if (!items || items->empty() || !items->is_array_of_tables())
            fail(*node, display_ + " parameters: expected a list of tables, e.g. parameters = [{ key = "
                                   "\"core.length\", values = [\"2 m\", \"3 m\"] }]");
        std::set<std::string> seen;
        long n_points = 1;
        for (size_t i = 0; i < items->size(); ++i) {
            const toml::table& item = *(*items)[i].as_table();
            const std::string display = display_ + " parameters #" + std::to_string(i + 1);
            check_keys(item, "parameter", display);
            read_parameter(root, item, display, out);
            for (const std::string& key : out.parameters.back().keys)
                if (!seen.insert(key).second)
                    fail(*item.get("key"), display + " key = \"" + key + "\" is varied twice; expected each key in "
                                                                         "one parameter only");
            n_points *= static_cast<long>(out.values.back().size());
            if (n_points > kMaxSweepPoints)
                fail(item, display_ + " has more than " + std::to_string(kMaxSweepPoints) +
                               " points; expected fewer values or steps");
        }
    }

    void read_parameter(const toml::table& root, const toml::table& item, const std::string& display,
                        CaseSweep::Impl& out) const {
        const toml::node* key_node = item.get("key");
        if (!key_node) fail(item, display + " has no key; expected e.g. key = \"rest_paper.thickness\"");
        std::vector<const toml::node*> key_nodes;
        if (const toml::array* list = key_node->as_array()) {
            for (const toml::node& k : *list) key_nodes.push_back(&k);
        } else {
            key_nodes.push_back(key_node);
        }
        if (key_nodes.empty()) fail(*key_node, display + " key = []: expected at least one key path");
        SweepParameter p;
        std::vector<KeyPath> paths;
        const KeySpec* spec = nullptr;
        for (const toml::node* k : key_nodes) {
            if (!k->is_string())
                fail(*k, display + " key: expected a dotted key path in quotes, e.g. key = \"core.length\", or a "
                                   "list of them");
            const std::string text(*k->value<std::string_view>());
            const auto [path, leaf] = resolve(root, text, *k, display);
            if (spec && (leaf->kind != spec->kind || leaf->dimension != spec->dimension))
                fail(*k, display + " key = \"" + text + "\" is a " + kind_name(*leaf) + ", but \"" + p.keys.front() +
                             "\" is a " + kind_name(*spec) + "; expected keys of one kind in one parameter");
            spec = leaf;
            p.keys.push_back(text);
            paths.push_back(path);
        }
        p.name = p.keys.front();
        p.dimension = spec->dimension;
        p.numeric = spec->kind == ValueKind::quantity || spec->kind == ValueKind::integer;
        const std::string what = display + " (" + p.name + ")";
        std::vector<Value> values;
        const toml::node* list = item.get("values");
        const toml::node* from = item.get("from");
        if (list && (from || item.get("to") || item.get("steps")))
            fail(*list, what + " gives values and a range (from, to, steps); expected one of them");
        if (list) {
            read_values(*list, *spec, what, p, values);
            if (spec->kind == ValueKind::text || spec->kind == ValueKind::material)
                check_words(out, paths, values, *list->as_array(), what);
        } else if (from || item.get("to")) {
            read_range(item, *spec, what, p, values);
        } else {
            fail(item, what + " has no values; expected values = [...] or from = ..., to = ..., steps = N");
        }
        out.parameters.push_back(std::move(p));
        out.paths.push_back(std::move(paths));
        out.values.push_back(std::move(values));
    }

    // A word (a mesh level, a support type, a library material) is checked by
    // the case reader, which knows the words: each value alone, set in the
    // case, must read, or the value's line is named.
    void check_words(const CaseSweep::Impl& out, const std::vector<KeyPath>& paths, const std::vector<Value>& values,
                     const toml::array& list, const std::string& what) const {
        for (size_t v = 0; v < values.size(); ++v) {
            toml::table doc = parse_toml_text(out.text, path_);
            out.apply_options(doc);
            for (const KeyPath& path : paths) CaseSweep::Impl::set(doc, path, values[v]);
            try {
                parse_case_table(doc, path_);
            } catch (const InputError& e) {
                fail(list[v], what + " = " + std::get<std::string>(values[v]) +
                                  " is refused with the case's other values: " + e.what());
            }
        }
    }

    static std::string kind_name(const KeySpec& spec) {
        switch (spec.kind) {
            case ValueKind::quantity:
                return spec.dimension == Dimension::dimensionless ? "number" : dimension_name(spec.dimension);
            case ValueKind::integer: return "whole number";
            case ValueKind::text: return "text";
            case ValueKind::boolean: return "true/false";
            case ValueKind::material: return "material";
            default: return "table";
        }
    }

    // A dotted path ("supports.left.expanding.1.width") against the schema
    // and the case's document; returns the steps and the leaf's KeySpec.
    std::pair<KeyPath, const KeySpec*> resolve(const toml::table& root, const std::string& text,
                                               const toml::node& where, const std::string& display) const {
        const std::string what = display + " key = \"" + text + "\"";
        std::vector<std::string> words;
        std::stringstream in(text);
        for (std::string w; std::getline(in, w, '.');) words.push_back(w);
        if (text.empty() || text.back() == '.' || std::count(words.begin(), words.end(), "") > 0)
            fail(where, what + ": expected a dotted key path such as \"rest_paper.thickness\"");
        if (words.front() == "study" || words.front() == "calibration")
            fail(where, what + ": a sweep cannot vary its own table; expected a key of the scene");
        KeyPath path;
        std::string schema;  // "" = top level
        std::string shown;   // "[supports.left]"
        const toml::node* doc = &root;  // the case's node along the path, or null past it
        const std::string support_type = support_type_of(root);
        for (size_t i = 0; i < words.size(); ++i) {
            const std::string& word = words[i];
            const KeySpec* spec = find_key(schema, word);
            if (!spec) unknown(where, what, schema, shown, word);
            path.push_back({word, 0, schema});
            doc = doc && doc->is_table() ? doc->as_table()->get(word) : nullptr;
            shown = shown.empty() ? "[" + word + "]" : shown.substr(0, shown.size() - 1) + "." + word + "]";
            const bool last = i + 1 == words.size();
            if (last) {
                if (spec->kind == ValueKind::table || spec->kind == ValueKind::tables || spec->kind == ValueKind::band ||
                    spec->kind == ValueKind::list)
                    fail(where, what + ": " + shown + " is not a single value; expected a key inside it, e.g. \"" +
                                    text + "." + std::string(keys_of(child_table(schema, word, support_type)).front()) +
                                    "\"");
                return {path, spec};
            }
            if (spec->kind == ValueKind::tables) {
                // An item of an array of tables: the next word is its 1-based number.
                const std::string& number = words[++i];
                const toml::array* items = doc ? doc->as_array() : nullptr;
                const int n_items = items ? static_cast<int>(items->size()) : 0;
                int item = 0;
                try {
                    item = std::stoi(number);
                } catch (const std::exception&) {
                }
                if (item < 1 || item > n_items || std::to_string(item) != number)
                    fail(where, what + ": expected an item number 1 to " + std::to_string(n_items) + " of " + shown +
                                    " after '" + word + ".', e.g. \"" + word + ".1\"");
                path.push_back({"", item, schema});
                doc = &(*items)[static_cast<size_t>(item - 1)];
                shown = shown.substr(0, shown.size() - 1) + " #" + number + "]";
            } else if (spec->kind != ValueKind::table && spec->kind != ValueKind::material) {
                fail(where, what + ": " + shown + " is a single value, not a table; expected the path to end there");
            }
            schema = child_table(schema, word, support_type);
        }
        COREMODAL_ASSERT(false);
    }

    [[noreturn]] void unknown(const toml::node& where, const std::string& what, const std::string& schema,
                              const std::string& shown, const std::string& word) const {
        const std::vector<std::string_view> valid = keys_of(schema);
        fail(where, what + ": no key '" + word + "' " + (shown.empty() ? "at the top level" : "in " + shown) +
                        did_you_mean_or_choices(word, valid));
    }

    void read_values(const toml::node& node, const KeySpec& spec, const std::string& what, SweepParameter& p,
                     std::vector<Value>& values) const {
        const toml::array* list = node.as_array();
        if (!list || list->empty()) fail(node, what + " values: expected a non-empty list, e.g. values = [\"2 m\", \"3 m\"]");
        for (const toml::node& v : *list) {
            switch (spec.kind) {
                case ValueKind::quantity: {
                    const double si = quantity(v, spec, what);
                    p.si.push_back(si);
                    p.labels.push_back(v.is_string() ? std::string(*v.value<std::string_view>())
                                                     : format_quantity(si, spec.dimension));
                    values.push_back(v.is_string() ? Value(std::string(*v.value<std::string_view>())) : Value(si));
                    break;
                }
                case ValueKind::integer: {
                    const std::int64_t n = integer(v, spec, what);
                    p.si.push_back(static_cast<double>(n));
                    p.labels.push_back(std::to_string(n));
                    values.push_back(n);
                    break;
                }
                case ValueKind::boolean:
                    if (!v.is_boolean()) fail(v, what + ": expected true or false (no quotes)");
                    p.labels.push_back(*v.value<bool>() ? "true" : "false");
                    values.push_back(*v.value<bool>());
                    break;
                default:  // text, or a material by library name
                    if (!v.is_string())
                        fail(v, what + ": expected a string in quotes" +
                                    std::string(spec.kind == ValueKind::material
                                                    ? " (a library material; to vary one value of a material, use "
                                                      "a key such as \"core.material.E_z\")"
                                                    : ""));
                    p.labels.emplace_back(*v.value<std::string_view>());
                    values.push_back(p.labels.back());
            }
        }
    }

    void read_range(const toml::table& item, const KeySpec& spec, const std::string& what, SweepParameter& p,
                    std::vector<Value>& values) const {
        const toml::node* from = item.get("from");
        const toml::node* to = item.get("to");
        const toml::node* steps = item.get("steps");
        if (spec.kind != ValueKind::quantity && spec.kind != ValueKind::integer)
            fail(from ? *from : *to, what + " is " + kind_name(spec) + "; a range needs a number, expected values = [...]");
        if (!from || !to || !steps)
            fail(item, what + ": a range needs from, to and steps, e.g. from = \"2 m\", to = \"4 m\", steps = 5");
        const double lo = quantity(*from, spec, what + " from");
        const double hi = quantity(*to, spec, what + " to");
        const int n = static_cast<int>(integer(*steps, *find_key("parameter", "steps"), what + " steps"));
        std::string spacing = "linear";
        if (const toml::node* s = item.get("spacing")) {
            spacing = std::string(s->value_or<std::string_view>(""));
            if (spacing != "linear" && spacing != "log")
                fail(*s, what + " spacing = " + (s->is_string() ? "\"" + spacing + "\"" : std::string("?")) +
                             ": expected \"linear\" or \"log\"");
            if (spacing == "log" && !(lo > 0 && hi > 0))
                fail(*s, what + " spacing = \"log\" needs from and to above zero");
        }
        const RangeUnit unit = range_unit(*from, spec.dimension);
        for (int i = 0; i < n; ++i) {
            const double t = static_cast<double>(i) / (n - 1);
            double v = spacing == "log" ? lo * std::pow(hi / lo, t) : lo + t * (hi - lo);
            if (i == n - 1) v = hi;  // exactly the end the user wrote
            if (spec.kind == ValueKind::integer) {
                if (std::abs(v - std::round(v)) > kWholeNumberTolerance * std::max(1.0, std::abs(v)))
                    fail(*steps, what + ": from " + format_quantity(lo, spec.dimension) + " to " +
                                     format_quantity(hi, spec.dimension) + " in " + std::to_string(n) +
                                     " steps gives " + format_quantity(v, spec.dimension) +
                                     ", not a whole number; expected (to - from) divisible by steps - 1");
                const auto whole = static_cast<std::int64_t>(std::llround(v));
                p.si.push_back(static_cast<double>(whole));
                p.labels.push_back(std::to_string(whole));
                values.push_back(whole);
            } else {
                p.si.push_back(v);
                p.labels.push_back(unit.label(v));
                values.push_back(v);
            }
        }
    }
};

}  // namespace

void read_sweep_table(const toml::table& root, const std::string& path, std::string_view table,
                      CaseSweep::Impl& out, const std::optional<std::string>& mesh_override) {
    SweepReader(path, table).read(root, out, mesh_override);
}

std::pair<KeyPath, const KeySpec*> resolve_key_path(const toml::table& root, const std::string& key,
                                                    const toml::node& where, const std::string& where_path,
                                                    const std::string& display) {
    return SweepReader(where_path, "study").resolve_key(root, key, where, display);
}

}  // namespace coremodal::case_sweeping
