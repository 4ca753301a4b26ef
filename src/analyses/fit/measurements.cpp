// Reading a fit's measurements file (measurements.hpp).
#include "analyses/fit/measurements.hpp"

#include "common/error.hpp"
#include "scene/level_traits.hpp"
#include "scene/case_json_schema.hpp"  // quantity_pattern, the draft
#include "scene/toml_text.hpp"
#include "scene/units.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <regex>
#include <set>

namespace coremodal {
namespace {

class Reader {
public:
    explicit Reader(std::string path) : path_(std::move(path)) {}

    [[noreturn]] void fail(const toml::source_region& where, const std::string& what) const {
        if (where.begin.line == 0) throw InputError(path_ + ": " + what);
        throw InputError(path_ + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column) +
                         ": " + what);
    }

    void check_keys(const toml::table& t, const std::set<std::string>& allowed, const std::string& display) const {
        for (const auto& [key, value] : t) {
            if (allowed.count(std::string(key.str()))) continue;
            std::string list;
            for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
            fail(key.source(), "unknown key '" + std::string(key.str()) + "' in " + display + "; expected one of " + list);
        }
    }

    double quantity(const toml::node& node, Dimension d, const std::string& what, const char* example) const {
        double v = 0;
        if (const auto s = node.value<std::string_view>()) {
            try {
                v = parse_quantity(*s, d);
            } catch (const std::invalid_argument& e) {
                fail(node.source(), what + ": " + e.what());
            }
        } else if (const auto x = node.value<double>()) {
            v = *x;
        } else {
            fail(node.source(), what + ": expected a string with a unit, e.g. " + example);
        }
        if (!(v > 0) || !std::isfinite(v)) fail(node.source(), what + ": expected a positive value, e.g. " + example);
        return v;
    }

    FitParameterSpec parameter(const toml::node& node, size_t i) const {
        const std::string display = "parameters #" + std::to_string(i + 1);
        FitParameterSpec p;
        p.where = node.source();
        if (const auto s = node.value<std::string>()) {
            p.key = *s;
            return p;
        }
        const toml::table* t = node.as_table();
        if (!t) fail(node.source(), display + ": expected a key in quotes, e.g. \"core.material.E_z\", or "
                                              "{ key = \"...\", min = \"...\", max = \"...\" }");
        check_keys(*t, {"key", "min", "max"}, display);
        const auto key = (*t)["key"].value<std::string>();
        if (!key) fail(node.source(), display + " has no key; expected key = \"core.material.G_rz\"");
        p.key = *key;
        // The bound's unit is the key's; checked against it when the key is resolved (here: any positive number).
        for (const char* bound : {"min", "max"})
            if (const toml::node* b = t->get(bound)) {
                double v = 0;
                if (const auto x = b->value<double>()) v = *x;
                else if (const auto s = b->value<std::string_view>()) v = parse_any_quantity(*b, *s, display + " " + bound);
                else fail(b->source(), display + " " + bound + ": expected a number or a string with a unit");
                if (!(v > 0)) fail(b->source(), display + " " + bound + ": expected a positive value (fits are in log p)");
                (std::string(bound) == "min" ? p.min : p.max) = v;
            }
        if (p.min && p.max && *p.min >= *p.max) fail(node.source(), display + ": min must be below max");
        return p;
    }

    // A bound in any unit the key could have: the first dimension that reads it.
    double parse_any_quantity(const toml::node& node, std::string_view text, const std::string& what) const {
        for (Dimension d : {Dimension::pressure, Dimension::stiffness_per_area, Dimension::length, Dimension::density,
                            Dimension::dimensionless, Dimension::stiffness, Dimension::rotational_stiffness,
                            Dimension::mass})
            try {
                return parse_quantity(text, d);
            } catch (const std::invalid_argument&) {
            }
        fail(node.source(), what + " = \"" + std::string(text) + "\": not a number with a known unit");
    }

    Measurement measurement(const toml::table& t, size_t i) const {
        const std::string display = "[[measurement]] #" + std::to_string(i + 1);
        check_keys(t, {"case", "mode", "frequency", "uncertainty", "model"}, display);
        Measurement m;
        m.where = t.source();
        const auto need = [&](const char* key, const char* example) -> const toml::node& {
            const toml::node* n = t.get(key);
            if (!n) fail(t.source(), display + " has no " + key + "; expected e.g. " + key + " = " + example);
            return *n;
        };
        const toml::node& c = need("case", "\"iso-test.toml\"");
        if (!c.is_string()) fail(c.source(), display + " case: expected a case file name in quotes");
        const std::filesystem::path file(*c.value<std::string>());
        m.case_file = (file.is_absolute() ? file : std::filesystem::path(path_).parent_path() / file).lexically_normal().string();
        const toml::node& mode = need("mode", "\"bending n=1 m=0\"");
        const auto key = mode.is_string() ? parse_mode_label(*mode.value<std::string>()) : std::nullopt;
        if (!key) fail(mode.source(), display + " mode: expected a mode label as the run reports it, e.g. \"bending n=1 m=0\" "
                                                "(type n=N m=M, optionally \" #2\" for its second occurrence)");
        m.mode = *key;
        m.frequency_hz = quantity(need("frequency", "\"133.2 Hz\""), Dimension::frequency, display + " frequency", "\"133.2 Hz\"");
        if (const toml::node* u = t.get("uncertainty")) {
            m.uncertainty_hz = quantity(*u, Dimension::frequency, display + " uncertainty", "\"0.3 Hz\"");
        } else {
            m.uncertainty_hz = kDefaultRelativeUncertainty * m.frequency_hz;
            m.uncertainty_assumed = true;
        }
        if (const toml::node* model = t.get("model")) {
            const auto s = model->value<std::string>();
            const std::optional<ModelChoice> choice = s ? parse_model_choice(*s) : std::nullopt;
            if (!choice || !(*choice == ModelChoice::automatic || level_traits(*choice).sensitivities))
                fail(model->source(), display + " model: expected \"beam\", \"harmonic\" or \"auto\" (the levels a fit "
                                                "differentiates at)");
            m.model = *s;
        }
        return m;
    }

private:
    std::string path_;
};

}  // namespace

std::optional<ModeKey> parse_mode_label(const std::string& text) {
    // At most six digits each: std::stoi of a longer number throws out_of_range
    // (the fuzzer's find); no mode has a wave number or an occurrence that high.
    static const std::regex pattern(
        R"(^\s*([a-z_]+)\s+n\s*=\s*(\d{1,6})\s+m\s*=\s*(\d{1,6})\s*(?:#\s*(\d{1,6}))?\s*$)");
    std::smatch match;
    if (!std::regex_match(text, match, pattern)) return std::nullopt;
    ModeKey key{match[1].str(), std::stoi(match[2].str()), std::stoi(match[3].str()), 1};
    if (match[4].matched) key.occurrence = std::stoi(match[4].str());
    if (key.occurrence < 1) return std::nullopt;
    return key;
}

FitInput parse_fit_input(const std::string& text, const std::string& path) {
    FitInput in;
    in.path = path;
    in.document = std::make_shared<toml::table>(parse_toml_text(text, path));
    const toml::table& root = *in.document;
    const Reader r(path);
    r.check_keys(root, {"parameters", "measurement"}, "the measurements file");
    const toml::node* params = root.get("parameters");
    if (!params) r.fail(root.source(), "no parameters; expected e.g. parameters = [\"core.material.E_z\"]");
    const toml::array* list = params->as_array();
    if (!list || list->empty()) r.fail(params->source(), "parameters: expected a non-empty list of case-file keys");
    std::set<std::string> seen;
    for (size_t i = 0; i < list->size(); ++i) {
        in.parameters.push_back(r.parameter((*list)[i], i));
        in.parameter_nodes.push_back(&(*list)[i]);
        if (!seen.insert(in.parameters.back().key).second)
            r.fail((*list)[i].source(), "parameters: \"" + in.parameters.back().key + "\" is named twice");
    }
    const toml::node* ms = root.get("measurement");
    const toml::array* tables = ms ? ms->as_array() : nullptr;
    if (!tables || tables->empty() || !tables->is_array_of_tables())
        r.fail(ms ? ms->source() : root.source(),
               "no [[measurement]] tables; expected at least one, with case, mode and frequency");
    for (size_t i = 0; i < tables->size(); ++i) in.measurements.push_back(r.measurement(*(*tables)[i].as_table(), i));
    return in;
}

FitInput read_fit_input(const std::string& path) { return parse_fit_input(read_input_file(path, "measurements file"), path); }

std::string fit_json_schema() {
    using Json = nlohmann::ordered_json;
    const Json frequency{{"anyOf", Json::array({Json{{"type", "number"}, {"exclusiveMinimum", 0}},
                                                 Json{{"type", "string"},
                                                      {"pattern", quantity_pattern(Dimension::frequency, false)}}})}};
    // A bound's unit is its key's, checked when the key is resolved: here any number, with or without a unit.
    const Json bound{{"anyOf", Json::array({Json{{"type", "number"}},
                                             Json{{"type", "string"}, {"pattern", R"(^\s*[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?(\s*\S.*)?$)"}}})}};
    const Json key{{"type", "string"}, {"pattern", R"(^[a-z_]+(\.[A-Za-z_0-9]+)+$)"},
                   {"description", "a case-file key a [study] can vary, e.g. core.material.E_z"}};
    const Json parameter{{"anyOf", Json::array({key, Json{{"type", "object"},
                                                         {"additionalProperties", false},
                                                         {"required", Json::array({"key"})},
                                                         {"properties", Json{{"key", key}, {"min", bound}, {"max", bound}}}}})}};
    const Json measurement{
        {"type", "object"},
        {"additionalProperties", false},
        {"required", Json::array({"case", "mode", "frequency"})},
        {"properties",
         Json{{"case", Json{{"type", "string"}, {"description", "case file, relative to this file"}}},
              {"mode", Json{{"type", "string"},
                            {"pattern", R"(^\s*[a-z_]+\s+n\s*=\s*\d+\s+m\s*=\s*\d+\s*(#\s*[1-9]\d*)?\s*$)"},
                            {"description", "a mode label as the run reports it, e.g. \"bending n=1 m=0\""}}},
              {"frequency", frequency},
              {"uncertainty", frequency},
              {"model", Json{{"enum", Json::array({"beam", "harmonic", "auto"})}}}}}};
    const Json root{{"$schema", kJsonSchemaDraft},
                    {"title", "coremodal fit measurements file (docs/how-to/calibration.md, \"Fitting the model\")"},
                    {"type", "object"},
                    {"additionalProperties", false},
                    {"required", Json::array({"parameters", "measurement"})},
                    {"properties", Json{{"parameters", Json{{"type", "array"}, {"minItems", 1}, {"items", parameter}}},
                                        {"measurement", Json{{"type", "array"}, {"minItems", 1}, {"items", measurement}}}}}};
    return root.dump(2) + "\n";
}

}  // namespace coremodal
