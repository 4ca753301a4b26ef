// What `coremodal calibrate` writes besides the study's files and
// calibration.toml: calibration.csv (the table of k) and report.md.
#pragma once

#include "analyses/calibrate/calibrate.hpp"

#include <string>
#include <vector>

namespace coremodal {

std::string calibration_csv(const CaseSweep& sweep, const CalibrationOutcome& outcome);
std::string calibration_report_markdown(const CaseSweep& sweep, const StudyResult& result,
                                        const CalibrationOutcome& outcome, const std::vector<std::string>& pngs,
                                        const std::string& plot_problem);
// The law, its fit and its check in two lines, and where calibration.toml is.
std::string calibration_console(const Calibration& c, const std::string& out_dir);

}  // namespace coremodal
