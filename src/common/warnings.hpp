// Warnings for the user: values that look like slips (Scene::warnings), said
// once on stderr as "coremodal: warning: ...", from rank 0 only.
#pragma once

#include <string>
#include <vector>

namespace coremodal {

// Works with or without MPI started (`coremodal beam` and `check` run without).
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace coremodal
