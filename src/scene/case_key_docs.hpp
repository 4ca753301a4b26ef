// What each case-file key means and what it is when the file leaves it out,
// for people: the JSON Schema (scene/case_json_schema.hpp) shows both in
// editors. A table beside the key table (scene/case_schema.hpp), keyed by
// (table, key), so that table stays one short row per key;
// tests/unit/scene/test_case_key_docs.cpp checks that every schema key has a
// row here and every row a schema key, so the two cannot drift apart.
// docs/reference/case-files.md is the long form of the same text.
#pragma once

#include <string_view>
#include <vector>

namespace coremodal {

struct KeyDoc {
    std::string_view table;  // schema table, as in KeySpec ("" = top level)
    std::string_view key;
    // The default as a user would write it: a TOML value ("\"0.5 mm\"", "20",
    // "true") when there is one, "required" when the key must be given, else
    // words ("from the level", "none: bare core").
    std::string_view default_value;
    std::string_view description;  // one line
    // The values a string key accepts, separated by spaces ("" = any); the
    // reader's lists in scene/case_file.cpp.
    std::string_view choices = "";
};

// The default written "required" means the key must be present.
inline constexpr std::string_view kRequired = "required";

const std::vector<KeyDoc>& case_key_docs();
const KeyDoc* find_key_doc(std::string_view table, std::string_view key);

}  // namespace coremodal
