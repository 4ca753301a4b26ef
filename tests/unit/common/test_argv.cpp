// The command line split between coremodal and PETSc (common/argv.hpp):
// PETSc's options with their values go to PETSc, everything else stays in
// coremodal's order.
#include "common/argv.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace coremodal;

namespace {

SplitArguments split(const std::vector<const char*>& argv) {
    return split_petsc_arguments(static_cast<int>(argv.size()), argv.data());
}

}  // namespace

TEST_CASE("PETSc options and their values are split from coremodal's arguments", "[argv]") {
    const SplitArguments s = split({"coremodal", "run", "-eps_view", "cases/01.toml", "-st_pc_factor_mat_solver_type",
                                    "mumps", "--output", "out", "-q", "-eps_tol", "1e-10"});
    // A case file after an option is coremodal's, not the option's value.
    CHECK(s.ours == std::vector<std::string>{"coremodal", "run", "cases/01.toml", "--output", "out", "-q"});
    CHECK(s.petsc == std::vector<std::string>{"coremodal", "-eps_view", "-st_pc_factor_mat_solver_type", "mumps",
                                              "-eps_tol", "1e-10"});
}

TEST_CASE("A PETSc flag followed by an option takes no value", "[argv]") {
    const SplitArguments s = split({"coremodal", "run", "-log_view", "--no-plots", "-eps_monitor", "-m", "fine"});
    CHECK(s.ours == std::vector<std::string>{"coremodal", "run", "--no-plots", "-m", "fine"});
    CHECK(s.petsc == std::vector<std::string>{"coremodal", "-log_view", "-eps_monitor"});
}
