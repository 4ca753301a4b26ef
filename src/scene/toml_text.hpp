// Reading TOML text with toml++, safe from its undefined behaviour.
//
// toml++ 3.3.0 (Debian 12's libtomlplusplus) reaches __builtin_unreachable —
// undefined behaviour — whenever it asks whether a character in U+00A1 to
// U+0499 (°, µ, ³, ä, Greek, Cyrillic), U+2C5E to U+3057 (but U+3000) or
// U+FB26 to U+FEFE is whitespace (toml++ issue #190, fixed upstream after 3.3.0). It asks in keys,
// in bare values and whatever follows them up to a terminator, between
// tokens, and after a backslash in a multi-line string: a file holding only
// "ä" is enough (the case fuzzer's first finding, docs/validation/reliability.md).
//
// So toml++ never sees those characters: each becomes a private-use code
// point (from U+E000 on), which toml++ handles like any other character,
// and every string of the parsed document, every message, gets the original
// back. Line and column numbers stay those of the file (one code point for one).
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>


namespace coremodal {

// toml::parse(text, path) without the undefined behaviour; throws
// toml::parse_error as it does (restore_characters on its description gives
// the user's characters back) and InputError for a text holding the
// private-use code points U+E000 to U+EFFF this needs for itself.
toml::table parse_toml_text(std::string_view text, const std::string& path);

// The whole of a text file: `kind` names it in the messages ("case file",
// "winder file"); a folder, a file that cannot be opened or read is an
// InputError naming the path.
std::string read_input_file(const std::string& path, std::string_view kind);

// parse_toml_text with every syntax error an InputError
// "path:line:column: TOML syntax error: what; expected <expected>", in the
// user's characters and with control characters shown as '?'.
toml::table parse_toml_input(std::string_view text, const std::string& path, std::string_view expected);

// The user's characters back in a text made from the parsed document (a message).
std::string restore_characters(std::string_view text);

}  // namespace coremodal
