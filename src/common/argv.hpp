// argv-style arrays for C interfaces (PETSc's options, posix_spawn).
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

}  // namespace coremodal
