// The files of `coremodal fit` (docs/how-to/calibration.md, "Fitting the model to
// measured frequencies"): fit.toml (each parameter's value ± standard
// uncertainty, its start and bounds) and report.md (residuals per
// measurement, the sensitivity matrix, correlations, warnings).
#pragma once

#include "analyses/fit/fit.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

std::string fit_toml(const FitInput& input, const FitOutcome& outcome);
std::string fit_report_markdown(const FitInput& input, const FitOutcome& outcome,
                                const std::vector<std::string>& calibrated_files);
std::string fit_console(const FitOutcome& outcome);
// Each fitted case as "<case>-fitted.toml" in `folder` ("<case>-<model>-fitted.toml"
// when one case was fitted at two model levels); returns the file names.
std::vector<std::string> write_fitted_cases(const std::filesystem::path& folder, const FitOutcome& outcome);

}  // namespace coremodal
