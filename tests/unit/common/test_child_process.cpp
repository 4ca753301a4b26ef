// What coremodal reads back from a child's log (common/child_process.hpp).
#include "common/child_process.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

TEST_CASE("first_error_line picks coremodal's message out of a child's log", "[batch]") {
    CHECK(first_error_line("") == "");
    CHECK(first_error_line("some MPI warning\ncoremodal: error: x.toml:3:1: unknown key 'a'\nmore\n") ==
          "error: x.toml:3:1: unknown key 'a'");
    CHECK(first_error_line("noise\nPETSC ERROR: out of memory\nlast\n") == "PETSC ERROR: out of memory");
    CHECK(first_error_line("one\nlast line  \n\n") == "last line");
}
