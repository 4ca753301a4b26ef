#include "scene/toml_text.hpp"

#include "common/error.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace coremodal {
namespace {

// The code points toml++ 3.3.0 cannot test for whitespace: its lookup
// (is_non_ascii_horizontal_whitespace) splits U+00A0 to U+FEFF into blocks of
// 0x3FA, and blocks 0, 11 and 63 fall through to TOML_UNREACHABLE for every
// code point but the one whitespace each holds (U+00A0, U+3000, U+FEFF).
struct Range {
    char32_t first, last;
};
constexpr Range kUnsafe[] = {{0xA1, 0x499}, {0x2C5E, 0x2FFF}, {0x3001, 0x3057}, {0xFB26, 0xFEFE}};
constexpr char32_t kStandIn = 0xE000;  // private use: U+E000 to U+EFFF, in the order of kUnsafe
constexpr char32_t kStandInLast = 0xEFFF;

bool unsafe(char32_t c) {
    for (const Range& r : kUnsafe)
        if (c >= r.first && c <= r.last) return true;
    return false;
}
char32_t stand_in(char32_t c) {
    char32_t offset = 0;
    for (const Range& r : kUnsafe) {
        if (c <= r.last) return kStandIn + offset + (c - r.first);
        offset += r.last - r.first + 1;
    }
    return c;  // not reached for unsafe(c)
}
char32_t original(char32_t s) {
    char32_t offset = s - kStandIn;
    for (const Range& r : kUnsafe) {
        if (offset <= r.last - r.first) return r.first + offset;
        offset -= r.last - r.first + 1;
    }
    return s;  // a stand-in beyond the last range: none is made
}

// The code point of a well-formed 2- or 3-byte UTF-8 sequence at text[i]
// (its length in n), or 0: other bytes pass through untouched, and toml++
// judges them.
char32_t decode(std::string_view text, std::size_t i, std::size_t& n) {
    const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
    const auto continuation = [&](std::size_t k) { return (byte(k) & 0xC0u) == 0x80u; };
    const unsigned b = byte(i);
    if (b >= 0xC2 && b <= 0xDF && continuation(i + 1)) {
        n = 2;
        return ((b & 0x1Fu) << 6) | (byte(i + 1) & 0x3Fu);
    }
    if (b >= 0xE0 && b <= 0xEF && continuation(i + 1) && continuation(i + 2)) {
        n = 3;
        const char32_t c = ((b & 0x0Fu) << 12) | ((byte(i + 1) & 0x3Fu) << 6) | (byte(i + 2) & 0x3Fu);
        return c >= 0x800 ? c : 0;  // overlong: leave it to toml++
    }
    return 0;
}

void encode(char32_t c, std::string& out) {
    if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
    } else {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    }
    out += static_cast<char>(0x80 | (c & 0x3F));
}

// Every character for which `pick` is true replaced by `replace(c)`.
template <class Pick, class Replace>
std::string map_characters(std::string_view text, Pick pick, Replace replace) {
    std::string out;
    out.reserve(text.size() + text.size() / 2);
    for (std::size_t i = 0; i < text.size();) {
        std::size_t n = 1;
        const char32_t c = decode(text, i, n);
        if (c && pick(c)) {
            encode(replace(c), out);
        } else {
            out.append(text.substr(i, c ? n : 1));
        }
        i += c ? n : 1;
    }
    return out;
}

bool is_stand_in(char32_t c) { return c >= kStandIn && c <= kStandInLast; }

void restore_strings(toml::node& node) {
    if (toml::table* table = node.as_table()) {
        for (auto&& [key, value] : *table) restore_strings(value);
    } else if (toml::array* array = node.as_array()) {
        for (toml::node& item : *array) restore_strings(item);
    } else if (toml::value<std::string>* text = node.as_string()) {
        text->get() = restore_characters(text->get());
    }
}

}  // namespace

std::string restore_characters(std::string_view text) { return map_characters(text, is_stand_in, original); }

toml::table parse_toml_text(std::string_view text, const std::string& path) {
    std::size_t line = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
        std::size_t n = 1;
        if (text[i] == '\n') ++line;
        if (is_stand_in(decode(text, i, n)))
            throw InputError(path + ":" + std::to_string(line) +
                             ": a private-use character U+E000 to U+EFFF; expected none in a case file");
    }
    toml::table root = toml::parse(map_characters(text, unsafe, stand_in), path);
    restore_strings(root);
    return root;
}

std::string read_input_file(const std::string& path, std::string_view kind) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(path + ": is a folder; expected a " + std::string(kind) + " (.toml)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open " + std::string(kind) + " (" + std::strerror(errno) + ")");
    std::ostringstream contents;
    contents << in.rdbuf();
    if (in.bad()) throw InputError(path + ": cannot read " + std::string(kind) + " (" + std::strerror(errno) + ")");
    return contents.str();
}

toml::table parse_toml_input(std::string_view text, const std::string& path, std::string_view expected) {
    try {
        return parse_toml_text(text, path);
    } catch (const toml::parse_error& e) {
        std::string what = restore_characters(e.description());
        for (char& c : what)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
        const auto& at = e.source().begin;
        throw InputError(path + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                         ": TOML syntax error: " + what + "; expected " + std::string(expected));
    }
}

}  // namespace coremodal
