// The files of `coremodal sensitivity` (docs/how-to/calibration.md, "Sensitivities"):
// sensitivity.csv (one row per parameter, one column per mode and k) and
// report.md (the same table, the values differentiated at, the method).
#pragma once

#include "analyses/sensitivity/sensitivity.hpp"

#include <string>

namespace coremodal {

// The distinct modes a table shows: the first `kSensitivityTableModes`.
inline constexpr int kSensitivityTableModes = 6;

std::string sensitivity_csv(const SensitivityResult& r);
// The markdown table alone (rows: parameters; columns: modes, f2, k).
std::string sensitivity_table_markdown(const SensitivityResult& r);
std::string sensitivity_report_markdown(const std::string& case_name, const SensitivityResult& r);
// A plain-text table for the console.
std::string sensitivity_console(const SensitivityResult& r);

}  // namespace coremodal
