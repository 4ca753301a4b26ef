#include "scene/toml_text.hpp"

#include "common/error.hpp"

namespace coremodal {
namespace {

// The code points toml++ 3.3.0 cannot test for whitespace, as one index range.
constexpr char32_t kLatinFirst = 0xA1, kLatinLast = 0x499;
constexpr char32_t kCjkFirst = 0x2E4E, kCjkLast = 0x3247, kIdeographicSpace = 0x3000;
constexpr char32_t kStandIn = 0xF000;  // private use: U+F000 to U+F7FF
constexpr char32_t kStandInLast = 0xF7FF;

bool unsafe(char32_t c) {
    return (c >= kLatinFirst && c <= kLatinLast) || (c >= kCjkFirst && c <= kCjkLast && c != kIdeographicSpace);
}
char32_t stand_in(char32_t c) {
    return c <= kLatinLast ? kStandIn + (c - kLatinFirst) : kStandIn + (kLatinLast - kLatinFirst + 1) + (c - kCjkFirst);
}
char32_t original(char32_t s) {
    const char32_t i = s - kStandIn, n_latin = kLatinLast - kLatinFirst + 1;
    return i < n_latin ? kLatinFirst + i : kCjkFirst + (i - n_latin);
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
                             ": a private-use character U+F000 to U+F7FF; expected none in a case file");
    }
    toml::table root = toml::parse(map_characters(text, unsafe, stand_in), path);
    restore_strings(root);
    return root;
}

}  // namespace coremodal
