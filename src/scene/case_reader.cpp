// The case reader's tools: messages, the schema (unknown keys, value
// kinds) and typed values (scene/case_reader.hpp).
#include "scene/case_reader.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>

namespace coremodal::case_reading {


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

std::string CaseReader::location(const toml::source_region& where) const {
    if (where.begin.line == 0) return path_ + ": ";
    return path_ + ":" + std::to_string(where.begin.line) + ":" +
           std::to_string(where.begin.column) + ": ";
}

[[noreturn]] void CaseReader::fail(const toml::source_region& where, const std::string& what) const {
    throw InputError(location(where) + what);
}

[[noreturn]] void CaseReader::fail(const toml::node& where, const std::string& what) const {
    fail(where.source(), what);
}

std::string CaseReader::name_of(const Section& s, std::string_view key) {
    return s.display.empty() ? std::string(key) : s.display + " " + std::string(key);
}

std::string CaseReader::echo(const Section& s, std::string_view key, const toml::node& value) {
    return name_of(s, key) + " = " + show(value);
}

Section CaseReader::open(const toml::table& table, std::string display, std::string schema) const {
    Section s{&table, std::move(display), std::move(schema)};
    for (const auto& [key, value] : table) {
        const KeySpec* spec = find_key(s.schema, key.str());
        if (!spec) unknown_key(s, key);
        check_kind(s, *spec, value);
    }
    return s;
}

[[noreturn]] void CaseReader::unknown_key(const Section& s, const toml::key& key) const {
    const std::vector<std::string_view> valid = keys_of(s.schema);
    const std::string where = s.display.empty() ? "at the top level" : "in " + s.display;
    fail(key.source(), "unknown key '" + printable(key.str()) + "' " + where + did_you_mean_or_choices(key.str(), valid));
}

void CaseReader::check_kind(const Section& s, const KeySpec& spec, const toml::node& value) const {
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

std::string CaseReader::quantity_hint(Dimension d) {
    if (d == Dimension::dimensionless) return "a plain number";
    const std::string name = dimension_name(d);
    return (name.front() == 'a' ? "an " : "a ") + name + ": a plain number in " + si_unit(d) +
           " or a string with a unit (" + accepted_units(d) + "), e.g. \"" + example_of(d) +
           "\"";
}

std::string CaseReader::example_of(Dimension d) {
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

const toml::node* CaseReader::get(const Section& s, std::string_view key) {
    return s.table->get(key);
}

std::optional<std::string> CaseReader::text(const Section& s, std::string_view key) const {
    const toml::node* node = get(s, key);
    if (!node) return std::nullopt;
    return std::string(*node->value<std::string_view>());
}

std::optional<std::string> CaseReader::choice(const Section& s, std::string_view key,
                                              const std::vector<std::string_view>& allowed) const {
    const std::optional<std::string> value = text(s, key);
    if (!value) return std::nullopt;
    if (std::find(allowed.begin(), allowed.end(), *value) != allowed.end()) return value;
    fail(*get(s, key), echo(s, key, *get(s, key)) + ": unknown value" + did_you_mean(*value, allowed, '"') +
                           "; expected one of " + join(allowed));
}

double CaseReader::to_si(const toml::node& node, Dimension d, const std::string& what) const {
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

std::optional<double> CaseReader::quantity(const Section& s, std::string_view key) const {
    const toml::node* node = get(s, key);
    if (!node) return std::nullopt;
    const KeySpec* spec = find_key(s.schema, key);
    COREMODAL_ASSERT(spec && spec->kind == ValueKind::quantity);
    const double v = to_si(*node, spec->dimension, echo(s, key, *node));
    check_range(s, *spec, *node, v);
    check_plausible(s, *spec, *node, v);
    return v;
}

void CaseReader::check_plausible(const Section& s, const KeySpec& spec, const toml::node& node, double v) const {
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

std::optional<std::string> CaseReader::likely_unit(double v, Dimension d, const PlausibleRange& p) {
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

void CaseReader::check_range(const Section& s, const KeySpec& spec, const toml::node& node,
                             double v) const {
    if (const std::optional<std::string> why = out_of_range(spec, v, node.is_number() ? show(node) : ""))
        fail(node, name_of(s, spec.key) + " = " + format_quantity(v, spec.dimension) + " " + *why);
}

std::optional<int> CaseReader::integer(const Section& s, std::string_view key) const {
    const toml::node* node = get(s, key);
    if (!node) return std::nullopt;
    const KeySpec* spec = find_key(s.schema, key);
    COREMODAL_ASSERT(spec && spec->kind == ValueKind::integer);
    const std::int64_t v = *node->value<std::int64_t>();
    if (const std::optional<std::string> why = integer_out_of_range(*spec, v)) fail(*node, echo(s, key, *node) + " " + *why);
    return static_cast<int>(v);
}

std::optional<Section> CaseReader::section(const Section& parent, std::string_view key,
                                           std::string schema) const {
    const toml::node* node = get(parent, key);
    if (!node) return std::nullopt;
    const std::string display = parent.display.empty()
                                    ? "[" + std::string(key) + "]"
                                    : parent.display.substr(0, parent.display.size() - 1) +
                                          "." + std::string(key) + "]";
    return open(*node->as_table(), display, std::move(schema));
}

double CaseReader::required(const Section& s, std::string_view key, const std::string& expected) const {
    if (const std::optional<double> v = quantity(s, key)) return *v;
    fail(s.table->source(),
         s.display + " " + std::string(key) + " is missing; expected " + expected);
}

void CaseReader::at_most_one(const Section& s, std::string_view a, std::string_view b) const {
    if (get(s, a) && get(s, b))
        fail(*get(s, b), echo(s, b, *get(s, b)) + " and " + echo(s, a, *get(s, a)) +
                             " are both given; expected exactly one of them");
}

}  // namespace coremodal::case_reading
