// Reading a case file (TOML) into a Scene. All checks of user input happen
// here, with messages of the form
//   FILE:LINE:COL: [table] key = value: what is wrong; what is expected
// thrown as InputError. Unknown keys are errors and suggest the nearest valid key.
#pragma once

#include "scene/scene.hpp"

#include <string>
#include <string_view>

namespace coremodal {

// Parses the file at `path`. Throws InputError on any problem (missing or
// unreadable file, TOML syntax error, unknown key, wrong unit, out-of-range value).
Scene parse_case_file(const std::string& path);

// Same, from text already in memory; `path` is used in messages and to resolve
// relative mesh file names.
Scene parse_case_text(std::string_view text, const std::string& path);

// parse_case_table (a document already parsed): scene/case_table.hpp.

}  // namespace coremodal
