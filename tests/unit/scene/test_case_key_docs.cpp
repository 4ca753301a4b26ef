#include "common/error.hpp"
#include "scene/case_file.hpp"
#include "scene/case_schema.hpp"
#include "scene/mesh_levels.hpp"

#include "support/case_errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

TEST_CASE("Every case-file key has a description and a default, and is declared once", "[schema][case_key_docs]") {
    SECTION("each key of the key table has text in its row") {
        for (const KeySpec& spec : case_schema()) {
            INFO("[" << spec.table << "] " << spec.key);
            CHECK_FALSE(spec.text.description.empty());
            CHECK_FALSE(spec.text.default_value.empty());
        }
    }
    SECTION("no key has two rows") {
        for (const KeySpec& spec : case_schema()) {
            INFO("[" << spec.table << "] " << spec.key);
            CHECK(find_key(spec.table, spec.key) == &spec);
        }
    }
    SECTION("every table of a key has a title") {
        for (const KeySpec& spec : case_schema()) {
            if (spec.table.empty()) continue;
            INFO("[" << spec.table << "] " << spec.key);
            CHECK(std::any_of(schema_tables().begin(), schema_tables().end(),
                              [&](const TableTitle& t) { return t.table == spec.table; }));
        }
    }
    SECTION("the mesh level choices are the levels of mesh_levels.hpp") {
        std::string levels;
        for (const MeshLevel& level : kMeshLevels) levels += (levels.empty() ? "" : " ") + std::string(level.name);
        for (const char* table : {"mesh", "study", "calibration"}) {
            const std::string_view key = std::string_view(table) == "mesh" ? "level" : "mesh";
            CHECK(find_key(table, key)->text.choices == levels);
        }
    }
}

namespace {

const std::string kCore =
    "[core]\n"
    "inner_diameter = \"76 mm\"\n"
    "outer_diameter = \"106 mm\"\n"
    "length = \"1.5 m\"\n";

std::string chucks(const std::string& left_extra, const std::string& bearing) {
    return kCore +
           "[supports]\ntype = \"chucks\"\n"
           "[supports.left]\ninserted_length = \"110 mm\"\n" +
           left_extra +
           "[[supports.left.expanding]]\ncenter = \"70 mm\"\nwidth = \"40 mm\"\n"
           "[supports.left.bearing]\n" +
           bearing;
}

}  // namespace

TEST_CASE("The documented choices of a string key are the reader's, in its order", "[schema][case_key_docs]") {
    struct Probe {
        std::string_view table, key;
        std::string text;  // the key set to "nonsense"
    };
    const Probe probes[] = {
        {"", "model", "model = \"nonsense\"\n" + kCore},
        {"supports", "type", kCore + "[supports]\ntype = \"nonsense\"\n"},
        {"mesh", "level", kCore + "[mesh]\nlevel = \"nonsense\"\n"},
        {"mesh", "element", kCore + "[mesh]\nelement = \"nonsense\"\n"},
        {"chuck", "interface", chucks("interface = \"nonsense\"\n", "type = \"rigid\"\n")},
        {"bearing", "type", chucks("", "type = \"nonsense\"\n")},
    };
    for (const Probe& p : probes) {
        INFO("[" << p.table << "] " << p.key);
        // "solid harmonic auto beam" -> "expected one of solid, harmonic, auto, beam"
        std::string expected = "expected one of ";
        for (const char c : find_key(p.table, p.key)->text.choices) expected += c == ' ' ? std::string(", ") : std::string(1, c);
        CHECK_THAT(error_of(p.text), Catch::Contains("unknown value") && Catch::Contains(expected));
    }
    SECTION("and the probes' base texts are valid cases") {
        CHECK(error_of(chucks("interface = \"bonded\"\n", "type = \"rigid\"\n")) == "(no error)");
    }
}
