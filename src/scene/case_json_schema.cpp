// The JSON Schema is built as a toml++ table and written with toml++'s JSON
// formatter, which does the quoting and escaping; no JSON library needed.
#include "scene/case_json_schema.hpp"

#include "common/error.hpp"
#include "scene/case_schema.hpp"
#include "scene/materials_library.hpp"
#include "scene/toml_text.hpp"
#include "scene/unit_symbols.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <sstream>

namespace coremodal {
namespace {

// A plain number as the reader's from_chars takes it: 76, 0.5, .5, 1e-3, 6.5E9.
constexpr std::string_view kNumberPattern = R"((\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?)";

std::string ref(std::string_view table) {
    return "#/definitions/" + std::string(table);
}

toml::table ref_to(std::string_view table) {
    return toml::table{{"$ref", ref(table)}};
}

// The schema table of the items of an array of tables ([[...]]).
std::string item_table(std::string_view key) {
    return key == "parameters" ? "parameter" : std::string(key);
}

// One unit symbol as a regular expression matching what the reader's
// normalisation accepts: "^" and superscripts optional ("kg/m^3", "kg/m3",
// "kg/m³"), spaces around "/" and "*", "µm" for "um".
std::string unit_regex(std::string_view symbol) {
    if (symbol == "um") return "(u|µ)m";
    std::string out;
    for (std::size_t i = 0; i < symbol.size(); ++i) {
        const char c = symbol[i];
        if (c == '^' && i + 1 < symbol.size()) {
            const char digit = symbol[++i];
            out += std::string("\\^?(") + digit + "|" + (digit == '2' ? "²" : "³") + ")";
        } else if (c == '/') {
            out += "\\s*/\\s*";  // not escaped: some regex dialects (Rust's, in taplo) refuse a backslash before "/"
        } else if (c == '*') {
            out += "\\s*\\*\\s*";
        } else {
            out += c;
        }
    }
    return out;
}

// A string quantity: a number, then a unit of dimension `d` (none for a
// dimensionless key, any unit for a sweep's from/to, whose dimension is the
// varied key's). A key that cannot be negative takes no minus sign.
std::string unit_pattern(Dimension d, bool signed_number, bool any_unit) {
    std::string unit;
    if (any_unit) {
        unit = "(\\s*\\S.*)?";
    } else if (d != Dimension::dimensionless) {
        unit = "\\s*(";
        bool first = true;
        for (std::string_view symbol : unit_symbols(d)) {
            if (!first) unit += '|';
            unit += unit_regex(symbol);
            first = false;
        }
        unit += ")";
    }
    return std::string("^\\s*") + (signed_number ? "[+-]?" : "\\+?") + std::string(kNumberPattern) + unit + "\\s*$";
}

std::string bound_text(double value, Dimension d) {
    return format_quantity(value, d);
}

// "A length: a plain number in m, or a string with a unit (m, mm, ...).
// Range: > 0 m, <= 5 m. Plausible: ... Default: ..."
std::string description(const KeySpec& spec, const KeyText& doc) {
    std::string text(doc.description);
    text += ".";
    if (spec.kind == ValueKind::quantity) {
        if (spec.table == "parameter") {
            text += " A number, or a string with the unit of the varied key.";
        } else if (spec.dimension == Dimension::dimensionless) {
            text += " A plain number.";
        } else {
            text += std::string(" Unit: ") + dimension_name(spec.dimension) + ", a plain number in " +
                    si_unit(spec.dimension) + " or a string with a unit (";
            bool first = true;
            for (std::string_view symbol : unit_symbols(spec.dimension)) {
                if (!first) text += ", ";
            text += symbol;
                first = false;
            }
            text += ").";
        }
    }
    if (spec.kind == ValueKind::quantity || spec.kind == ValueKind::integer) {
        std::string range;
        const Dimension d = spec.kind == ValueKind::integer ? Dimension::dimensionless : spec.dimension;
        if (std::isfinite(spec.min)) range += (spec.min_exclusive ? "> " : ">= ") + bound_text(spec.min, d);
        if (std::isfinite(spec.max)) range += (range.empty() ? "<= " : ", <= ") + bound_text(spec.max, d);
        if (!range.empty()) text += " Range: " + range + ".";
        if (!spec.plausible.empty())
            text += " Plausible: " + bound_text(spec.plausible.low, spec.dimension) + " to " +
                    bound_text(spec.plausible.high, spec.dimension) + " (" + std::string(spec.plausible.why) +
                    "); outside it the reader warns.";
    }
    if (!doc.choices.empty()) {
        std::string choices(doc.choices);
        for (char& c : choices)
            if (c == ' ') c = '/';
        text += " One of " + choices + ".";
    }
    text += " Default: " + std::string(doc.default_value) + ".";
    return text;
}

// The default as a JSON value, when it is written as a TOML value ("20",
// "\"0.5 mm\"", "true"); words ("from the level") have none.
std::optional<toml::table> default_value(std::string_view written) {
    if (written == kRequired) return std::nullopt;
    try {
        toml::table parsed = parse_toml_text("value = " + std::string(written), "<default>");
        if (parsed.size() != 1 || !parsed.contains("value")) return std::nullopt;
        return parsed;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

toml::array strings(const std::vector<std::string>& items) {
    toml::array out;
    for (const std::string& s : items) out.push_back(s);
    return out;
}

std::vector<std::string> words(std::string_view text) {
    std::vector<std::string> out;
    std::istringstream in{std::string(text)};
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

toml::table quantity_schema(const KeySpec& spec) {
    toml::table number{{"type", "number"}};
    if (std::isfinite(spec.min)) number.insert(spec.min_exclusive ? "exclusiveMinimum" : "minimum", spec.min);
    if (std::isfinite(spec.max)) number.insert("maximum", spec.max);
    const bool signed_number = !(std::isfinite(spec.min) && spec.min >= 0);
    toml::table text{{"type", "string"},
                     {"pattern", unit_pattern(spec.dimension, signed_number, spec.table == "parameter")}};
    return toml::table{{"anyOf", toml::array{std::move(number), std::move(text)}}};
}

toml::table library_name_schema() {
    std::vector<std::string> names;
    for (const LibraryMaterial& m : material_library()) names.emplace_back(m.name);
    return toml::table{{"type", "string"}, {"enum", strings(names)}};
}

toml::table material_schema() {
    return toml::table{{"anyOf", toml::array{library_name_schema(), ref_to("material")}}};
}

// The schema of one key's value, before its description and default.
toml::table value_schema(const KeySpec& spec, const KeyText& doc) {
    switch (spec.kind) {
        case ValueKind::quantity:
            return quantity_schema(spec);
        case ValueKind::integer: {
            toml::table t{{"type", "integer"}};
            if (std::isfinite(spec.min)) t.insert("minimum", static_cast<std::int64_t>(spec.min));
            if (std::isfinite(spec.max)) t.insert("maximum", static_cast<std::int64_t>(spec.max));
            return t;
        }
        case ValueKind::text: {
            // A material's base is a library name.
            if (spec.table == "material" && spec.key == "base") return library_name_schema();
            toml::table t{{"type", "string"}};
            if (!doc.choices.empty()) t.insert("enum", strings(words(doc.choices)));
            // A sweep parameter may set several keys together: key = ["a.b", "c.d"].
            if (spec.table == "parameter" && spec.key == "key")
                return toml::table{
                    {"anyOf", toml::array{std::move(t), toml::table{{"type", "array"},
                                                                    {"minItems", 1},
                                                                    {"items", toml::table{{"type", "string"}}}}}}};
            return t;
        }
        case ValueKind::table:
            // [supports] left/right: clamp or chuck, settled in table_schema by type.
            if (spec.table == "supports") return toml::table{{"anyOf", toml::array{ref_to("clamp"), ref_to("chuck")}}};
            return ref_to(child_table(spec.table, spec.key, ""));
        case ValueKind::material:
            return material_schema();
        case ValueKind::band: {
            const KeySpec frequency{"analysis", "band", ValueKind::quantity, Dimension::frequency, 0.0};
            return toml::table{{"type", "array"},
                               {"minItems", 2},
                               {"maxItems", 2},
                               {"items", quantity_schema(frequency)}};
        }
        case ValueKind::boolean:
            return toml::table{{"type", "boolean"}};
        case ValueKind::tables:
            return toml::table{{"type", "array"}, {"minItems", 1}, {"items", ref_to(item_table(spec.key))}};
        case ValueKind::list:
            return toml::table{{"type", "array"}, {"minItems", 1}};
    }
    return {};
}

// One schema table as a JSON object schema: its keys, which are required,
// no others (the reader refuses unknown keys in every table).
toml::table table_schema(std::string_view table, std::string_view title) {
    toml::table properties;
    toml::array required;
    for (const KeySpec& spec : case_schema()) {
        if (spec.table != table) continue;
        const KeyText& doc = spec.text;
        toml::table property = value_schema(spec, doc);
        property.insert("description", description(spec, doc));
        if (std::optional<toml::table> d = default_value(doc.default_value))
            d->get("value")->visit([&](const auto& value) { property.insert("default", value); });
        properties.insert(spec.key, std::move(property));
        if (doc.default_value == kRequired) required.push_back(std::string(spec.key));
    }
    toml::table out{{"type", "object"},
                    {"description", title},
                    {"properties", std::move(properties)},
                    {"additionalProperties", false}};
    if (!required.empty()) out.insert("required", std::move(required));
    if (table == "supports") {
        // type = "chucks": both ends are chucks; otherwise clamp zones.
        const auto ends = [](std::string_view kind) {
            return toml::table{{"properties", toml::table{{"left", ref_to(kind)}, {"right", ref_to(kind)}}}};
        };
        out.insert("if", toml::table{{"properties", toml::table{{"type", toml::table{{"const", "chucks"}}}}},
                                     {"required", toml::array{"type"}}});
        out.insert("then", ends("chuck"));
        out.insert("else", ends("clamp"));
    }
    return out;
}


}  // namespace

std::string quantity_pattern(Dimension d, bool negative_allowed) {
    return unit_pattern(d, negative_allowed, false);
}

std::string case_json_schema() {
    toml::table definitions;
    std::set<std::string_view> described;
    for (const TableTitle& t : schema_tables()) {
        definitions.insert(t.table, table_schema(t.table, t.title));
        described.insert(t.table);
    }
    for (const KeySpec& spec : case_schema())
        COREMODAL_ASSERT(spec.table.empty() || described.contains(spec.table));

    toml::table schema = table_schema("", "");
    // [core] is required, except in a file for `coremodal traction` alone,
    // which needs only [traction] (docs/how-to/traction.md).
    schema.insert_or_assign("anyOf", toml::array{toml::table{{"required", toml::array{"core"}}},
                                                 toml::table{{"required", toml::array{"traction"}}}});
    schema.insert_or_assign("$schema", kJsonSchemaDraft);
    schema.insert_or_assign("title", "coremodal case file");
    schema.insert_or_assign("description",
                            "A coremodal case file (docs/reference/case-files.md): the core, optional rest paper, how it is "
                            "held, what to compute and how fine to mesh. Generated by `coremodal schema` from "
                            "src/scene/case_keys.cpp; `coremodal check` is the full check.");
    schema.insert_or_assign("definitions", std::move(definitions));

    std::ostringstream out;
    out << toml::json_formatter{schema} << "\n";
    return out.str();
}

}  // namespace coremodal
