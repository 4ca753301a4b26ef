// The results of `coremodal select` (docs/how-to/durability.md, "Choosing a core"):
// selection.csv (per stand and core: the largest roll weight, the widths
// the speed and the weight allow; what `python3 -m coremodal selection-plot`
// draws), reels.csv (the verdict on each reel asked), summary.json and
// report.md.
#pragma once

#include "analyses/select/core_selection.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

// `seconds`: the command's wall time so far (summary.json timing_s.total).
void write_selection_tables(const std::filesystem::path& dir, const SelectionScene& scene, const SelectionResult& r,
                            double seconds);

std::string selection_report_markdown(const SelectionScene& scene, const SelectionResult& r,
                                      const std::vector<std::string>& pngs, const std::string& plot_problem);

// The console lines: the width verdict's assumptions, one per stand and core, one per reel.
std::vector<std::string> selection_console_lines(const SelectionScene& scene, const SelectionResult& r);

}  // namespace coremodal
