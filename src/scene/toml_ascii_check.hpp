// A check of a case file's text before toml++ reads it.
//
// toml++ 3.3.0 (Debian 12's libtomlplusplus) reaches __builtin_unreachable,
// which is undefined behaviour, when it asks whether certain non-ASCII
// characters are whitespace (U+00A1 to U+0499 — °, µ, ³, ä, Greek, Cyrillic —
// and U+2E4E to U+3247; toml++ issue #190, fixed upstream after 3.3.0). It asks
// in keys, in bare values, between tokens, and after a backslash in a
// multi-line "..." string. The case fuzzer found it (docs/validation.md,
// "Reliability"). TOML allows non-ASCII text only in strings and comments, and
// no case-file key is non-ASCII, so this check refuses it everywhere else —
// with a located message — before toml++ sees it. In string values
// ("60 °", "920 kg/m³") and comments it stays allowed.
#pragma once

#include <string>
#include <string_view>

namespace coremodal {

// Throws InputError "PATH:LINE:COL: ..." at the first non-ASCII character
// outside a string value or a comment, in a quoted key, or right after a
// backslash (or a line-ending backslash's whitespace) in a multi-line basic string.
void check_ascii_outside_strings(std::string_view text, const std::string& path);

}  // namespace coremodal
