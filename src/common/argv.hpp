// argv-style arrays for C interfaces (PETSc's options, posix_spawn), and the
// command line split between coremodal's own arguments and PETSc's.
#pragma once

#include <string>
#include <vector>

namespace coremodal {

// Pointers into `strings` (which must outlive the result), null-terminated.
inline std::vector<char*> c_strings(std::vector<std::string>& strings) {
    std::vector<char*> out;
    for (auto& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

struct SplitArguments {
    std::vector<std::string> ours;   // argv[0] and coremodal's own arguments
    std::vector<std::string> petsc;  // argv[0] and PETSc's
};

// A PETSc option is a single dash followed by a word with an underscore
// ("-eps_view", "-log_view", "-st_pc_factor_mat_solver_type"); its value, if
// any, is the next argument unless that looks like an option or a case file.
// Everything else is coremodal's, in its order.
SplitArguments split_petsc_arguments(int argc, const char* const* argv);

}  // namespace coremodal
