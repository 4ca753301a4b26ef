// The case file's keys as a JSON Schema (draft-07), generated from the key
// table (scene/case_schema.hpp: each key's range, description and default,
// each table's title) and the units (scene/units.hpp). `coremodal
// schema` prints it; editors with TOML support (taplo, VS Code's Even Better
// TOML) then complete keys, show each key's meaning, unit, range and default,
// and underline unknown keys, wrong types and unknown units as you type.
//
// What it checks is a subset of the reader's checks: each key's table, type,
// unit (the pattern accepts a number followed by a unit of the key's
// dimension), the SI bounds of plain numbers, the values of string choices,
// required keys, and [supports.left]/[supports.right] as clamps or chucks by
// [supports] type. Not checked: bounds of strings with a unit, relations
// between keys (inner < outer diameter, one of wall and outer_diameter),
// material admissibility, plausible ranges (in the descriptions only). The
// reader (`coremodal check`) stays the judge; the schema is for editing.
//
// Two-drum winder files ([winder], docs/how-to/winder.md) and a fit's measurements
// files have readers and schemas of their own (winder/winder_scene.hpp,
// analyses/fit/measurements.hpp; `coremodal schema --winder`, `--fit`).
#pragma once

#include "scene/units.hpp"

#include <string>

namespace coremodal {

inline constexpr const char* kJsonSchemaDraft = "http://json-schema.org/draft-07/schema#";

// The schema as JSON text (keys sorted, two-space indentation).
std::string case_json_schema();

// The pattern (ECMAScript regular expression) a quantity written as a string
// must match: a number, then a unit of dimension `d` ("76 mm", "920 kg/m3",
// "76 µm"), no unit for a dimensionless key; no minus sign unless
// `negative_allowed`.
std::string quantity_pattern(Dimension d, bool negative_allowed);

}  // namespace coremodal
