// CSV fields (output/csv.hpp) as RFC 4180 writes them, checked by reading
// them back with a reader written from the RFC's grammar.
#include "output/csv.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace coremodal;

namespace {

// The fields of one CSV record (RFC 4180, section 2): a quoted field runs to
// the next lone quote, "" inside it is one quote; line breaks in quotes are data.
std::vector<std::string> read_record(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
        else if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) fields.emplace_back();
        else fields.back() += c;
    }
    return fields;
}

}  // namespace

TEST_CASE("A CSV field is quoted only when it must be, and reads back as written", "[output][csv]") {
    CHECK(csv_field("bending n=1 m=0") == "bending n=1 m=0");
    CHECK(csv_field("") == "");
    CHECK(csv_field("a, \"b\"") == "\"a, \"\"b\"\"\"");
    CHECK(csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
    CHECK(csv_field("two\nlines") == "\"two\nlines\"");
    CHECK(csv_field("cr\rhere") == "\"cr\rhere\"");
    const std::vector<std::string> texts = {"plain", "a,b", "\"", "x \"y\", z\nnext line", ",,", "error: x, \"y\" | z"};
    std::string line;
    for (const auto& t : texts) {
        if (!line.empty()) line += ',';
        line += csv_field(t);
    }
    CHECK(read_record(line) == texts);
}
