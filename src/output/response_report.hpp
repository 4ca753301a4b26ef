// The files of `coremodal response` (docs/how-to/response.md): response.csv (per
// speed and probe: the amplitude in total and per order), peaks.csv,
// summary.json and report.md; response.png comes from `python3 -m
// coremodal response-plot`.
#pragma once

#include "analyses/response/response.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

void write_response_tables(const std::filesystem::path& dir, const Scene& scene, const ResponseSetup& setup,
                           const ResponseResult& result);

// pngs: the pictures drawn ("" problem), or why none were.
std::string response_report_markdown(const Scene& scene, const ResponseSetup& setup, const ResponseResult& result,
                                     const std::vector<std::string>& pngs, const std::string& plot_problem);

// The console lines: the peaks, the safe speeds and the checks.
std::string response_console_summary(const Scene& scene, const ResponseResult& result);

}  // namespace coremodal
