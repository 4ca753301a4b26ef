#include "scene/case_key_docs.hpp"
#include "scene/case_schema.hpp"
#include "scene/mesh_levels.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;

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
