// The one scheme every command's summary.json follows (docs/reference/results.md,
// docs/schemas/summary.schema.json): written with nlohmann-json in the order
// the keys are inserted, `schema_version` first, then `program`, `command`,
// `case`; `timing_s` {`total`, ...} and, where a roll spins in a stand, the
// I-5 safe web speeds in one shape.
#pragma once

#include "beam/speeds.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

using Json = nlohmann::ordered_json;

// summary.json's scheme; a removed or renamed key raises it.
constexpr int kSummarySchemaVersion = 2;

// {schema_version, program: "coremodal X.Y.Z", command, case: {name, file,
// description}}: the head of every summary.json, in that order.
Json summary_head(std::string_view command, const std::string &case_name,
                  const std::string &case_file, const std::string &description);

// A number JSON can hold: not finite becomes null (never expected; every
// writer input is checked upstream).
Json number_or_null(double value);

// The strings as a JSON array.
Json string_array(const std::vector<std::string> &items);

// Ilomäki's I-5 speeds (beam/speeds.hpp): {f1_hz, dp_m, safe_web_speed:
// [{safe, v_safe_m_s, v_safe_m_min}]}, or {not_given: why}.
Json safe_web_speed_json(const RollSpeeds &speeds);

// The document as text: two-space indentation, UTF-8, a final newline.
std::string json_text(const Json &document);

} // namespace coremodal
