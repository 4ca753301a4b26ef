// What `coremodal batch` writes: the table of its cases (f1, FE/Timoshenko,
// D, v_safe, time) on the console, as OUT/batch.csv and as OUT/batch.md.
#pragma once

#include "analyses/batch/batch.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace coremodal {

void print_batch_table(std::ostream& out, const std::vector<BatchCase>& cases);
std::string batch_csv(const std::vector<BatchCase>& cases);
std::string batch_markdown(const std::vector<BatchCase>& cases);

}  // namespace coremodal
