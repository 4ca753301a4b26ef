// The one table of case-file keys. It drives the check of every table in a
// case file (unknown keys, value types, ranges) and the "did you mean"
// suggestion; docs/reference/case-files.md documents the same keys.
#pragma once

#include "scene/units.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

// Which kind of TOML value a key takes.
enum class ValueKind {
    quantity,  // number (SI) or string with a unit, see units.hpp
    integer,   // TOML integer
    text,      // TOML string
    table,     // TOML table
    material,  // library name (string) or inline table
    band,      // array of two frequencies
    boolean,   // true or false
    tables,    // array of tables, [[...]]
    list,      // array of values, [a, b, ...]
};

// Where a value normally lies, with the reason. Outside it a value is most
// likely a unit slip (E = 6.5, a plain number, is 6.5 Pa, not 6.5 GPa): the
// case reader warns, naming the key, and for a plain number suggests the
// unit that brings it nearest `typical`. A warning, not an error: an odd
// scene may be meant. Empty (low = high = 0) for keys without one.
struct PlausibleRange {
    double low = 0, high = 0;  // SI
    double typical = 0;        // SI: the order of magnitude a suggestion aims at
    std::string_view why;      // where the range comes from, for the warning
    bool empty() const { return !(high > low); }
};

// What a key means and what it is when the file leaves it out, for people:
// the JSON Schema (scene/case_json_schema.hpp) shows both in editors;
// docs/reference/case-files.md is the long form of the same text.
struct KeyText {
    // The default as a user would write it: a TOML value ("\"0.5 mm\"", "20",
    // "true") when there is one, "required" when the key must be given, else
    // words ("from the level", "none: bare core"). Those of the reader
    // (scene/case_file.cpp, scene/case_sweep.cpp, scene/chuck_contact.hpp,
    // scene/scene.hpp).
    std::string_view default_value;
    std::string_view description;  // one line
    // The values a string key accepts, separated by spaces ("" = any); the
    // reader's lists in scene/case_file.cpp.
    std::string_view choices = "";
};

// The default written "required" means the key must be present.
inline constexpr std::string_view kRequired = "required";

// A case-file key, declared once: its table, kind, unit, range, plausible
// range and words (issue 34: "case-file keys in one table"). Schema tables:
// material tables ([core.material], [rest_paper.material]) share "material";
// [supports.left] and [supports.right] share "clamp".
struct KeySpec {
    std::string_view table;  // "" for the top level
    std::string_view key;
    ValueKind kind;
    Dimension dimension = Dimension::dimensionless;  // quantities only
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_exclusive = false;  // value must be > min rather than >= min
    PlausibleRange plausible{};  // quantities only; a warning outside it
    KeyText text{};              // description and default (set by the table's row)
};

// A schema table other than the top level, with its title (the JSON
// Schema's description of the object).
struct TableTitle {
    std::string_view table, title;
};
const std::vector<TableTitle>& schema_tables();

// The library material of a part whose file gives no material (each use is
// echoed as an assumption).
inline constexpr std::string_view kDefaultCoreMaterial = "paperboard_core";
inline constexpr std::string_view kDefaultRestPaperMaterial = "rest_paper";
inline constexpr std::string_view kDefaultChuckMaterial = "steel";
// The default material of the schema table that owns a material key
// ("core", "rest_paper", "chuck"); "" for other tables.
std::string_view default_material(std::string_view owner_table);

const std::vector<KeySpec>& case_schema();

// The one range check of a key's value, for every reader of case keys (the
// case reader, the [study]/[calibration] sweep reader): what is wrong with
// `v`, worded to follow "KEY = VALUE" ("must be positive", "is too large:
// expected at most 50 m; plain numbers are in m, ..."), or nothing when it is
// inside the key's bounds. `plain_number`: the value as written when the file
// gave a plain number (the hint that plain numbers are SI), else "".
std::optional<std::string> out_of_range(const KeySpec& spec, double v, std::string_view plain_number = "");
// The same for an integer key: "is out of range; expected 1 to 10000".
std::optional<std::string> integer_out_of_range(const KeySpec& spec, std::int64_t v);
// The schema table of the table at `key` inside schema table `parent`: the
// key itself, except [supports.left]/[supports.right] ("clamp" or "chuck" as
// `support_type` says) and every material table ("material").
std::string child_table(std::string_view parent, std::string_view key, std::string_view support_type);
const KeySpec* find_key(std::string_view table, std::string_view key);
std::vector<std::string_view> keys_of(std::string_view table);

// Case-insensitive edit distance (insertions, deletions, substitutions and
// swaps of neighbours each count 1).
std::size_t edit_distance(std::string_view a, std::string_view b);
// The candidate nearest to `word`, or "" when none is near enough to be a typo.
std::string_view nearest(std::string_view word, const std::vector<std::string_view>& candidates);
// "; did you mean 'x'?" when x is nearest (quote '"' for a TOML string
// value, '\'' for a key, command or option), else "".
std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates, char quote = '\'');
// did_you_mean, or "; expected one of a, b, c" when no candidate is near.
std::string did_you_mean_or_choices(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace coremodal
