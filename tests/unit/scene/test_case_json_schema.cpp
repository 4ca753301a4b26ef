#include "scene/case_json_schema.hpp"
#include "scene/case_schema.hpp"
#include "scene/unit_symbols.hpp"
#include "scene/units.hpp"

#include <catch2/catch.hpp>

#include <cctype>
#include <regex>
#include <stdexcept>
#include <string>

using namespace coremodal;

namespace {

// A strict JSON reader that only says whether the text is one JSON value
// (RFC 8259) and nothing after it; enough to know editors can load it.
class JsonCheck {
public:
    explicit JsonCheck(const std::string& text) : s_(text) {}
    bool valid() {
        try {
            value();
            space();
            return i_ == s_.size();
        } catch (const std::runtime_error&) {
            return false;
        }
    }

private:
    void space() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    char peek() {
        space();
        if (i_ >= s_.size()) throw std::runtime_error("end");
        return s_[i_];
    }
    void expect(char c) {
        if (peek() != c) throw std::runtime_error("expected");
        ++i_;
    }
    void word(std::string_view w) {
        space();
        if (s_.compare(i_, w.size(), w) != 0) throw std::runtime_error("word");
        i_ += w.size();
    }
    void string() {
        expect('"');
        while (i_ < s_.size() && s_[i_] != '"') {
            if (static_cast<unsigned char>(s_[i_]) < 0x20) throw std::runtime_error("control");
            if (s_[i_] == '\\') {
                ++i_;
                if (i_ >= s_.size() || std::string_view("\"\\/bfnrtu").find(s_[i_]) == std::string_view::npos)
                    throw std::runtime_error("escape");
            }
            ++i_;
        }
        expect('"');
    }
    void number() {
        const std::regex json_number(R"(-?(0|[1-9]\d*)(\.\d+)?([eE][+-]?\d+)?)");
        std::size_t end = i_;
        while (end < s_.size() && std::string_view("+-.eE0123456789").find(s_[end]) != std::string_view::npos) ++end;
        if (!std::regex_match(s_.substr(i_, end - i_), json_number)) throw std::runtime_error("number");
        i_ = end;
    }
    void value() {
        const char c = peek();
        if (c == '{') {
            ++i_;
            if (peek() == '}') return void(++i_);
            for (;;) {
                string();
                expect(':');
                value();
                if (peek() == '}') return void(++i_);
                expect(',');
            }
        }
        if (c == '[') {
            ++i_;
            if (peek() == ']') return void(++i_);
            for (;;) {
                value();
                if (peek() == ']') return void(++i_);
                expect(',');
            }
        }
        if (c == '"') return string();
        if (c == 't') return word("true");
        if (c == 'f') return word("false");
        if (c == 'n') return word("null");
        number();
    }
    const std::string& s_;
    std::size_t i_ = 0;
};

bool accepted_by_reader(const std::string& text, Dimension d) {
    try {
        parse_quantity(text, d);
        return true;
    } catch (const std::invalid_argument&) {
        return false;
    }
}

}  // namespace

TEST_CASE("The case-file JSON Schema is one JSON document naming every key", "[schema][case_json_schema]") {
    const std::string schema = case_json_schema();

    SECTION("it is well-formed JSON") {
        CHECK(JsonCheck(schema).valid());
        CHECK_FALSE(JsonCheck(schema + "}").valid());  // the checker itself refuses a broken text
        CHECK_FALSE(JsonCheck("{\"a\": 1,}").valid());
    }
    SECTION("it says it is draft-07 and has a table for every schema table") {
        CHECK(schema.find("\"$schema\" : \"http://json-schema.org/draft-07/schema#\"") != std::string::npos);
        for (const char* table : {"core", "rest_paper", "material", "supports", "clamp", "chuck", "expanding",
                                  "bearing", "analysis", "mesh", "study", "calibration", "parameter"})
            CHECK(schema.find("\"#/definitions/" + std::string(table) + "\"") != std::string::npos);
    }
    SECTION("every key of the key table is a property") {
        for (const KeySpec& spec : case_schema()) {
            INFO("[" << spec.table << "] " << spec.key);
            CHECK(schema.find("\"" + std::string(spec.key) + "\" : {") != std::string::npos);
        }
    }
    SECTION("no table takes keys it does not list, as the reader refuses them") {
        CHECK(schema.find("\"additionalProperties\" : true") == std::string::npos);
        CHECK(schema.find("\"additionalProperties\" : false") != std::string::npos);
    }
}

TEST_CASE("A quantity's unit pattern accepts exactly the units the reader takes", "[schema][case_json_schema]") {
    const Dimension dimensions[] = {Dimension::length,   Dimension::pressure,           Dimension::density,
                                    Dimension::frequency, Dimension::stiffness_per_area, Dimension::angle,
                                    Dimension::speed,     Dimension::mass,               Dimension::stiffness,
                                    Dimension::rotational_stiffness};
    SECTION("every unit of every dimension, in the pattern of its own dimension only") {
        for (const Dimension d : dimensions) {
            const std::regex pattern(quantity_pattern(d, true));
            for (const Dimension other : dimensions)
                for (std::string_view symbol : unit_symbols(other)) {
                    const std::string text = "2.5 " + std::string(symbol);
                    INFO(text << " as a " << dimension_name(d));
                    CHECK(std::regex_match(text, pattern) == accepted_by_reader(text, d));
                }
        }
    }
    SECTION("the spellings the reader normalises, and the ones it refuses") {
        const std::regex length(quantity_pattern(Dimension::length, false));
        for (const char* ok : {"76 mm", "76mm", " 76 mm ", "7.6e1 mm", ".5 m", "+76 mm", "76 µm", "76 um"}) {
            INFO(ok);
            CHECK(std::regex_match(std::string(ok), length));
            CHECK(accepted_by_reader(ok, Dimension::length));
        }
        for (const char* bad : {"76", "76 MM", "76 kg", "mm", "-76 mm", "76 mmm"}) {
            INFO(bad);
            CHECK_FALSE(std::regex_match(std::string(bad), length));
        }
        const std::regex density(quantity_pattern(Dimension::density, false));
        for (const char* ok : {"920 kg/m^3", "920 kg/m3", "920 kg/m³", "920 kg / m^3", "0.92 g/cm^3"}) {
            INFO(ok);
            CHECK(std::regex_match(std::string(ok), density));
            CHECK(accepted_by_reader(ok, Dimension::density));
        }
        const std::regex plain(quantity_pattern(Dimension::dimensionless, true));
        CHECK(std::regex_match(std::string("-0.3"), plain));
        CHECK_FALSE(std::regex_match(std::string("0.3 mm"), plain));
    }
}
