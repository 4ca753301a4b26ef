// A case's name names its results folder (results/<name>, results/<name>-study,
// ...): it is a name, not a path. "../../x" or "/tmp/abs" would write
// outside results/, "" or "." would make results/ itself the output and
// rotate away every other case's results in it (issue 33).
#pragma once

#include <string>

namespace coremodal {

// What is wrong with `name` as a case name, "" when nothing: it must be
// one folder name — not empty, not "." or "..", without '/' or '\',
// control characters or a leading '-', and at most kMaxCaseNameBytes long
// (a file name has at most 255 bytes on Linux file systems, and the
// results folder adds a suffix such as "-sensitivity.partial-4194304").
std::string case_name_problem(const std::string& name);

inline constexpr size_t kMaxCaseNameBytes = 200;

// What a case name may be, for the messages ("expected ...").
inline constexpr const char* kCaseNameExpected =
    "expected a plain name such as \"rest-roll-300\" (letters, digits, spaces, '-', '_', '.'; no '/'), which "
    "names the results folder results/<name>";

}  // namespace coremodal
