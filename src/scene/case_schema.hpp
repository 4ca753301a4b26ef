// The one table of case-file keys. It drives the check of every table in a
// case file (unknown keys, value types, ranges) and the "did you mean"
// suggestion; docs/case-files.md documents the same keys.
#pragma once

#include "scene/units.hpp"

#include <limits>
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
};

// Schema tables. Material tables ([core.material], [rest_paper.material]) share
// "material"; [supports.left] and [supports.right] share "clamp".
struct KeySpec {
    std::string_view table;  // "" for the top level
    std::string_view key;
    ValueKind kind;
    Dimension dimension = Dimension::dimensionless;  // quantities only
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_exclusive = false;  // value must be > min rather than >= min
};

const std::vector<KeySpec>& case_schema();
const KeySpec* find_key(std::string_view table, std::string_view key);
std::vector<std::string_view> keys_of(std::string_view table);

// Case-insensitive edit distance (insertions, deletions, substitutions and
// swaps of neighbours each count 1).
std::size_t edit_distance(std::string_view a, std::string_view b);
// The candidate nearest to `word`, or "" when none is near enough to be a typo.
std::string_view nearest(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace coremodal
