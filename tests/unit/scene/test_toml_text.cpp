// toml++ 3.3.0 reaches undefined behaviour when it tests some non-ASCII
// characters for whitespace; parse_toml_text hides them from it and gives
// them back (the case fuzzer's findings: tests/fuzz_regressions/toml-unreachable-*).
#include "scene/toml_text.hpp"

#include "common/error.hpp"
#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;

TEST_CASE("parse_toml_text gives back every string exactly as written", "[scene][case_file]") {
    const toml::table t = parse_toml_text(
        "a = \"60 \xc2\xb0\"  # Ilom\xc3\xa4ki\nb = ['10 \xc2\xb5m', \"kg/m\xc2\xb3\"]\n"
        "c = { d = \"\xd0\x96 \xe3\x80\x81 \xe3\x80\x80 \xe2\xb1\xa0 \xef\xb3\xbf \xef\xbb\xbe\" }\n"
        "e = \"\"\"\\\n  \xc2\xa7 after a line-ending backslash\"\"\"\n",
        "x.toml");
    CHECK(t["a"].value<std::string>() == "60 \xc2\xb0");
    CHECK(t["b"][0].value<std::string>() == "10 \xc2\xb5m");
    CHECK(t["b"][1].value<std::string>() == "kg/m\xc2\xb3");
    // Cyrillic, CJK comma, ideographic space, U+2C60, U+FCFF, U+FEFE: one from every unsafe range.
    CHECK(t["c"]["d"].value<std::string>() == "\xd0\x96 \xe3\x80\x81 \xe3\x80\x80 \xe2\xb1\xa0 \xef\xb3\xbf \xef\xbb\xbe");
    CHECK(t["e"].value<std::string>() == "\xc2\xa7 after a line-ending backslash");
    CHECK(restore_characters("plain ASCII") == "plain ASCII");
}

TEST_CASE("Non-ASCII text where TOML allows none is a located syntax error with the user's character", "[scene][case_file]") {
    // Each of these reached __builtin_unreachable inside toml++ before.
    CHECK_THROWS_WITH(parse_case_text("\xc3\xa4", "x.toml"), Catch::StartsWith("x.toml:1:1: TOML syntax error: ") &&
                                                                  Catch::Contains("\xc3\xa4"));
    CHECK_THROWS_WITH(parse_case_text("l=2\"\xd2\x8b", "x.toml"), Catch::StartsWith("x.toml:1:"));
    CHECK_THROWS_WITH(parse_case_text("\xef\xb3\xbf = 1", "x.toml"), Catch::StartsWith("x.toml:1:1:") &&  // U+FCFF
                                                                      Catch::Contains("\xef\xb3\xbf"));
    CHECK_THROWS_WITH(parse_case_text("\xe2\xb1\xa0 = 1", "x.toml"), Catch::StartsWith("x.toml:1:1:"));  // U+2C60
    CHECK_THROWS_WITH(parse_case_text("[core]\ninner_diameter = 76\xc2\xb5m\n", "x.toml"),
                      Catch::StartsWith("x.toml:2:") && Catch::Contains("TOML syntax error"));
    // A quoted non-ASCII key reaches the reader, whose message names it as written.
    CHECK_THROWS_WITH(parse_case_text("\"Ilom\xc3\xa4ki\" = 1\n", "x.toml"),
                      Catch::Contains("unknown key 'Ilom\xc3\xa4ki' at the top level"));
    CHECK_THROWS_WITH(parse_case_text("d = \"\xee\x80\x80\"\n", "x.toml"), Catch::Contains("private-use character"));
}
