// The files of `coremodal campbell` (docs/how-to/campbell.md): campbell.csv (speed,
// tracked mode, frequency, whirl), critical_speeds.csv, summary.json and
// report.md; campbell.png comes from `python3 -m coremodal campbell-plot`.
#pragma once

#include "analyses/campbell/campbell.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

void write_campbell_tables(const std::filesystem::path& dir, const Scene& scene, const RotationSpec& rotation,
                           const CampbellResult& result);

// pngs: the pictures drawn ("" problem), or why none were.
std::string campbell_report_markdown(const Scene& scene, const CampbellResult& result,
                                     const std::vector<std::string>& pngs, const std::string& plot_problem);

// The console lines: the critical speeds and the safe web speed.
std::string campbell_console_summary(const Scene& scene, const CampbellResult& result);

}  // namespace coremodal
