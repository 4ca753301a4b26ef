// What the isolated singleton sets before MPI starts, and takes back after
// (common/mpi_start.hpp): the test process has started MPI already, so this
// checks the environment a later run would start with, not MPI itself.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "common/mpi_start.hpp"

namespace {

std::string variable(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "(unset)";
}

}  // namespace

TEST_CASE("A process no launcher started runs MPI as an isolated singleton on pml ob1, then gives the variables back",
          "[mpi_start]") {
    if (std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK")) return;
    unsetenv("OMPI_MCA_pml");
    unsetenv("OMPI_MCA_ess_singleton_isolated");
    setenv("OMPI_MCA_orte_create_session_dirs", "1", 1);  // the user's: kept
    {
        coremodal::IsolatedMpiSingleton isolated;
        CHECK(variable("OMPI_MCA_pml") == "ob1");
        CHECK(variable("OMPI_MCA_ess_singleton_isolated") == "1");
        CHECK(variable("OMPI_MCA_orte_create_session_dirs") == "1");
        isolated.started();
    }
    CHECK(variable("OMPI_MCA_pml") == "(unset)");
    CHECK(variable("OMPI_MCA_ess_singleton_isolated") == "(unset)");
    CHECK(variable("OMPI_MCA_orte_create_session_dirs") == "1");
    unsetenv("OMPI_MCA_orte_create_session_dirs");
}

TEST_CASE("Under a launcher the singleton leaves the environment alone", "[mpi_start]") {
    const bool had = std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr;
    if (!had) setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
    unsetenv("OMPI_MCA_pml");
    coremodal::IsolatedMpiSingleton isolated;
    CHECK(variable("OMPI_MCA_pml") == "(unset)");
    isolated.started();
    if (!had) unsetenv("OMPI_COMM_WORLD_SIZE");
}
