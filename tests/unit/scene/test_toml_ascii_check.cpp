// Non-ASCII text outside strings and comments is refused before toml++ reads
// it (toml++ 3.3.0 reaches undefined behaviour on some of it: the case fuzzer's
// first finding, tests/fuzz_regressions/toml-unreachable-*).
#include "scene/toml_ascii_check.hpp"

#include "common/error.hpp"
#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;

namespace {

std::string error_of(const std::string& text) {
    try {
        check_ascii_outside_strings(text, "x.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("Non-ASCII text in string values and comments is allowed", "[scene][case_file]") {
    CHECK(error_of("# Ilom\xc3\xa4ki, K\xc3\xb6nig\nsegment_angle = \"60 \xc2\xb0\"\ndensity = \"920 kg/m\xc2\xb3\"\n") ==
          "(no error)");
    CHECK(error_of("values = [\"10 \xc2\xb5m\", '20 \xc2\xb5m'] # \xc2\xb5\nt = { a = \"\xc3\xa4\", b = ['\xc3\xa4'] }\n") ==
          "(no error)");
    CHECK(error_of("description = \"\"\"two\nlines \xc3\xa4 \\\"quoted\\\" \"\"\"\nx = '''\xc3\xa4\\'''\n") == "(no error)");
    // Whole cases with such text read as before.
    const std::string core = "[core]\ninner_diameter = \"76 mm\"  # \xc3\xa4\nwall = \"15 mm\"\nlength = \"1 m\"\n";
    CHECK(parse_case_text("description = \"K\xc3\xb6nig\"\n" + core, "x.toml").description == "K\xc3\xb6nig");
}

TEST_CASE("Non-ASCII text anywhere else is refused with its line and column", "[scene][case_file]") {
    CHECK(error_of("\xc3\xa4") ==
          "x.toml:1:1: a non-ASCII character (byte 0xC3) outside a quoted string; expected non-ASCII text only in "
          "strings and comments, e.g. segment_angle = \"60 deg\"");
    CHECK_THAT(error_of("[core]\ninner_diameter = 76\xc2\xb5m\n"), Catch::StartsWith("x.toml:2:20: a non-ASCII character (byte 0xC2) outside"));
    CHECK_THAT(error_of("\"Ilom\xc3\xa4ki\" = 1\n"), Catch::StartsWith("x.toml:1:6: a non-ASCII character (byte 0xC3) in a quoted key"));
    CHECK_THAT(error_of("[core.\"\xc2\xb5\"]\n"), Catch::Contains("in a quoted key"));
    CHECK_THAT(error_of("t = { \"\xc3\xa4\" = 1 }\n"), Catch::Contains("in a quoted key"));
    CHECK_THAT(error_of("d = \"\"\"\\\xc2\xa7\"\"\"\n"), Catch::Contains("right after a backslash"));
    CHECK_THAT(error_of("d = \"\"\"\\\n  \xc2\xa7\"\"\"\n"), Catch::StartsWith("x.toml:2:3: a non-ASCII character (byte 0xC2) first on the line after a line-ending backslash"));
    // parse_case_text runs the check first: the same message, from the reader.
    CHECK_THROWS_WITH(parse_case_text("\xc3\xa4", "x.toml"), Catch::StartsWith("x.toml:1:1: a non-ASCII character"));
}
