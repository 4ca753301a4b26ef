#include "scene/case_key_docs.hpp"
#include "common/error.hpp"
#include "scene/case_file.hpp"
#include "scene/case_schema.hpp"
#include "scene/mesh_levels.hpp"

#include "support/case_errors.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

TEST_CASE("Every case-file key has a description and a default, and every row a key", "[schema][case_key_docs]") {
    SECTION("each key of the key table has one row, with text in it") {
        for (const KeySpec& spec : case_schema()) {
            INFO("[" << spec.table << "] " << spec.key);
            const KeyDoc* doc = find_key_doc(spec.table, spec.key);
            REQUIRE(doc);
            CHECK_FALSE(doc->description.empty());
            CHECK_FALSE(doc->default_value.empty());
        }
    }
    SECTION("no row names a key the key table does not have") {
        for (const KeyDoc& doc : case_key_docs()) {
            INFO("[" << doc.table << "] " << doc.key);
            CHECK(find_key(doc.table, doc.key));
        }
    }
    SECTION("the two tables are the same length, so no key has two rows") {
        CHECK(case_key_docs().size() == case_schema().size());
    }
    SECTION("the mesh level choices are the levels of mesh_levels.hpp") {
        std::string levels;
        for (const MeshLevel& level : kMeshLevels) levels += (levels.empty() ? "" : " ") + std::string(level.name);
        for (const char* table : {"mesh", "study", "calibration"}) {
            const std::string_view key = std::string_view(table) == "mesh" ? "level" : "mesh";
            CHECK(find_key_doc(table, key)->choices == levels);
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
        for (const char c : find_key_doc(p.table, p.key)->choices) expected += c == ' ' ? std::string(", ") : std::string(1, c);
        CHECK_THAT(error_of(p.text), Catch::Contains("unknown value") && Catch::Contains(expected));
    }
    SECTION("and the probes' base texts are valid cases") {
        CHECK(error_of(chucks("interface = \"bonded\"\n", "type = \"rigid\"\n")) == "(no error)");
    }
}
