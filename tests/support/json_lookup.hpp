// Reading a value back from a JSON file the program wrote (summary.json,
// converge.json) by a dotted path of object keys, with nlohmann-json.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace coremodal {

// The value at "beam.fe_first_bending_hz" and the like; nullptr when the path
// is absent. Throws std::runtime_error ("invalid JSON ...") when the text is not JSON.
inline std::optional<nlohmann::json> json_at(const std::string& json, const std::string& path) {
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(json);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error(std::string("invalid JSON: ") + e.what());
    }
    const nlohmann::json* v = &root;
    std::istringstream keys(path);
    for (std::string key; std::getline(keys, key, '.');) {
        if (!v->is_object() || !v->contains(key)) return std::nullopt;
        v = &(*v)[key];
    }
    return *v;
}

// A number or a string by its dotted path; nullopt when absent or of another kind.
inline std::optional<double> json_number(const std::string& json, const std::string& path) {
    const auto v = json_at(json, path);
    return v && v->is_number() ? std::optional<double>(v->get<double>()) : std::nullopt;
}
inline std::optional<std::string> json_string(const std::string& json, const std::string& path) {
    const auto v = json_at(json, path);
    return v && v->is_string() ? std::optional<std::string>(v->get<std::string>()) : std::nullopt;
}

}  // namespace coremodal
