// Rigid against elastic chucks (analyses/run/rigid_comparison.hpp): the
// console table and rigid_vs_elastic.csv.
#pragma once

#include "results/run_report.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace coremodal {

void print_side_by_side(std::ostream& out, const std::vector<ModeShift>& shifts);
std::string side_by_side_csv(const std::vector<ModeShift>& shifts);

}  // namespace coremodal
