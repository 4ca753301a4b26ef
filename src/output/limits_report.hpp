// The files of `coremodal limits` (docs/how-to/limits.md): limits.csv (per
// rest-roll diameter every criterion's web speed and band, the governing one,
// the safe speed), amplitude.csv (the mid-span orbit against web speed at every
// diameter), summary.json (every number of them, the inputs' ranges, the
// verdict) and report.md opening with the verdict table; limits.png comes
// from `python3 -m coremodal limits-plot`.
#pragma once

#include "analyses/limits/limits.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

void write_limits_tables(const std::filesystem::path& dir, const Scene& scene, const LimitsResult& result);

// pngs: the pictures drawn ("" problem), or why none were.
std::string limits_report_markdown(const Scene& scene, const LimitsResult& result, const std::vector<std::string>& pngs,
                                   const std::string& plot_problem);

// The console lines before the verdict: the table per diameter and the
// warnings.
std::string limits_console_summary(const Scene& scene, const LimitsResult& result);

}  // namespace coremodal
