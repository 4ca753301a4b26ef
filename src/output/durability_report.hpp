// The results of `coremodal durability` (docs/how-to/durability.md): points.csv
// (the data with their log residuals), curves.csv (fit, confidence and
// prediction limits, reduced curves; what the plot draws),
// allowed_weights.csv (the weight each failure probability allows at 0.5, 1,
// 2, 5, 10, ... cycles), summary.json and report.md; the picture comes from
// `python3 -m coremodal durability-plot`.
#pragma once

#include "durability/durability_analysis.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

// `seconds`: the command's wall time so far (summary.json timing_s.total).
void write_durability_tables(const std::filesystem::path& dir, const DurabilityData& data,
                             const DurabilityAnalysis& a, double seconds);

// report.md; `pngs` the pictures drawn, `plot_problem` why there are none.
std::string durability_report_markdown(const DurabilityData& data, const DurabilityAnalysis& a,
                                       const std::vector<std::string>& pngs, const std::string& plot_problem);

// The steps as the console names them, one line each ({16}–{32}).
std::vector<std::string> durability_steps(const DurabilityData& data, const DurabilityAnalysis& a);

}  // namespace coremodal
