#include "scene/toml_ascii_check.hpp"

#include "common/error.hpp"

#include <cstdio>
#include <vector>

namespace coremodal {
namespace {

bool non_ascii(char c) { return static_cast<unsigned char>(c) >= 0x80; }
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// A walk over the text that knows only what decides where non-ASCII may
// stand: comments, strings, and whether a string is a key or a value.
class AsciiCheck {
public:
    AsciiCheck(std::string_view text, const std::string& path) : text_(text), path_(path) {}

    void run() {
        while (i_ < text_.size()) step();
    }

private:
    std::string_view text_;
    const std::string& path_;
    std::size_t i_ = 0;
    std::vector<char> open_;  // 'a' array, 't' inline table
    bool expect_key_ = true;  // a string here is a key (line start, after '{' or ',' in an inline table)
    bool in_header_ = false;  // inside [table] or [[table]]

    [[noreturn]] void fail(std::size_t at, const std::string& what) const {
        int line = 1, column = 1;
        for (std::size_t k = 0; k < at; ++k) {
            if (text_[k] == '\n') {
                ++line;
                column = 1;
            } else if ((static_cast<unsigned char>(text_[k]) & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
                ++column;
            }
        }
        char byte[8];
        std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(text_[at]));
        throw InputError(path_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": a non-ASCII character (byte " +
                         byte + ") " + what);
    }

    void step() {
        const char c = text_[i_];
        if (c == '#') {
            while (i_ < text_.size() && text_[i_] != '\n') ++i_;  // comments may hold any text
            return;
        }
        if (c == '"' || c == '\'') return string(c);
        if (non_ascii(c))
            fail(i_, "outside a quoted string; expected non-ASCII text only in strings and comments, "
                     "e.g. segment_angle = \"60 deg\"");
        if (c == '\n' && open_.empty()) {
            expect_key_ = true;
            in_header_ = false;
        } else if (c == '[') {
            if (open_.empty() && expect_key_) {
                in_header_ = true;
            } else {
                open_.push_back('a');
                expect_key_ = false;
            }
        } else if (c == ']') {
            if (in_header_) {
                expect_key_ = false;
            } else if (!open_.empty()) {
                open_.pop_back();
            }
        } else if (c == '{') {
            open_.push_back('t');
            expect_key_ = true;
        } else if (c == '}') {
            if (!open_.empty()) open_.pop_back();
            expect_key_ = false;
        } else if (c == '=') {
            expect_key_ = false;
        } else if (c == ',' && !open_.empty() && open_.back() == 't') {
            expect_key_ = true;
        }
        ++i_;
    }

    void string(char quote) {
        const bool key = expect_key_ || in_header_;
        const bool multi_line = text_.substr(i_, 3) == std::string(3, quote);
        const std::size_t delimiter = multi_line ? 3 : 1;
        i_ += delimiter;
        while (i_ < text_.size()) {
            const char c = text_[i_];
            if (multi_line ? text_.substr(i_, 3) == std::string(3, quote) : c == quote) {
                i_ += delimiter;
                return;
            }
            if (!multi_line && c == '\n') return;  // unterminated: toml++ says so
            if (key && non_ascii(c))
                fail(i_, "in a quoted key; expected one of the case-file keys, which are all ASCII (docs/case-files.md)");
            if (c == '\\' && quote == '"') {
                escape(multi_line);
                continue;
            }
            ++i_;
        }
    }

    // After a backslash in a "..." string: toml++ tests the next character
    // for whitespace in a multi-line string, and skips the whitespace after a
    // line-ending backslash.
    void escape(bool multi_line) {
        ++i_;
        if (i_ >= text_.size()) return;
        if (multi_line && non_ascii(text_[i_]))
            fail(i_, "right after a backslash in a multi-line string; expected an escape such as \\n or \\u00B0");
        if (multi_line && blank(text_[i_])) {
            while (i_ < text_.size() && blank(text_[i_])) ++i_;
            if (i_ < text_.size() && non_ascii(text_[i_]))
                fail(i_, "first on the line after a line-ending backslash in a multi-line string; expected "
                         "ASCII there, or the character written as an escape such as \\u00B0");
            return;
        }
        ++i_;  // the escaped character (\" or \\ never ends the string)
    }
};

}  // namespace

void check_ascii_outside_strings(std::string_view text, const std::string& path) { AsciiCheck(text, path).run(); }

}  // namespace coremodal
