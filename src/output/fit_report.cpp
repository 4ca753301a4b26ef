#include "output/fit_report.hpp"

#include "common/format.hpp"
#include "output/text_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace coremodal {
namespace {

std::string quantity_text(double v, Dimension d) { return format_quantity(v, d); }

std::string uncertainty_text(const FitParameter& p) {
    if (!p.uncertainty) return "not identifiable";
    return quantity_text(*p.uncertainty, p.dimension) + " (" + significant(100 * *p.uncertainty / p.value, 2) + " %)";
}

std::string toml_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    return out + "\"";
}

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

}  // namespace

std::string fit_toml(const FitInput& input, const FitOutcome& out) {
    std::ostringstream s;
    s << "# coremodal fit of " << input.path << ": values in SI (" << "Pa, Pa/m, kg/m^3, m); uncertainty: standard "
      << "uncertainty from the measurements' uncertainties (docs/how-to/calibration.md)\n"
      << "converged = " << (out.converged ? "true" : "false") << "\niterations = " << out.iterations
      << "\nchi2 = " << number(out.chi2) << "\nmeasurements = " << out.measurements.size() << "\n";
    for (const FitParameter& p : out.parameters) {
        s << "\n[[parameter]]\nkey = " << toml_string(p.key) << "\nvalue = " << number(p.value)
          << "\nvalue_text = " << toml_string(quantity_text(p.value, p.dimension)) << "\n";
        if (p.uncertainty) s << "uncertainty = " << number(*p.uncertainty) << "\n";
        else s << "identifiable = false\n";
        s << "start = " << number(p.start) << "\nmin = " << number(p.min) << "\nmax = " << number(p.max)
          << "\nat_bound = " << (p.at_bound ? "true" : "false") << "\n";
    }
    return s.str();
}

std::string fit_report_markdown(const FitInput& input, const FitOutcome& out,
                                const std::vector<std::string>& calibrated_files) {
    std::ostringstream s;
    s << "# Fit of " << input.path << "\n\n"
      << out.parameters.size() << " parameters fitted to " << out.measurements.size()
      << " measured frequencies by Levenberg–Marquardt in ln p with exact eigenvalue sensitivities "
      << "(docs/how-to/calibration.md): " << (out.converged ? "converged" : "NOT converged") << " after " << out.iterations
      << " iterations; χ² = Σ ((f_model − f_measured)/u)² from " << significant(out.chi2_start) << " to "
      << significant(out.chi2) << ".\n\n";
    if (!out.warnings.empty()) {
        s << "## Warnings\n\n";
        for (const std::string& w : out.warnings) s << "- **" << w << "**\n";
        s << "\n";
    }
    s << "## Parameters\n\n| parameter | start | fitted | standard uncertainty | bounds |\n|---|---|---|---|---|\n";
    for (const FitParameter& p : out.parameters)
        s << "| `" << p.key << "` | " << quantity_text(p.start, p.dimension) << " | " << quantity_text(p.value, p.dimension)
          << (p.at_bound ? " (at bound)" : "") << " | " << uncertainty_text(p) << " | "
          << quantity_text(p.min, p.dimension) << " … " << quantity_text(p.max, p.dimension) << " |\n";
    s << "\n## Residuals\n\n| case | level | mode | measured | u | start | fitted | residual / u |\n"
         "|---|---|---|---|---|---|---|---|\n";
    for (const FittedMeasurement& m : out.measurements)
        s << "| " << m.measurement.case_file << " | " << to_string(m.level) << " | " << m.measurement.mode.text() << " | "
          << significant(m.measurement.frequency_hz, 6) << " Hz | " << significant(m.measurement.uncertainty_hz, 3)
          << " Hz" << (m.measurement.uncertainty_assumed
                  ? " (assumed: " + significant(100 * kDefaultRelativeUncertainty, 2) + " %, none given)"
                  : "") << " | " << significant(m.start_hz, 6) << " Hz | " << significant(m.model_hz, 6) << " Hz | "
          << significant((m.model_hz - m.measurement.frequency_hz) / m.measurement.uncertainty_hz, 3) << " |\n";
    s << "\n## Sensitivity matrix d ln f / d ln p (at the fitted values)\n\n| measurement |";
    for (const FitParameter& p : out.parameters) s << " `" << p.key << "` |";
    s << "\n|---|";
    for (size_t j = 0; j < out.parameters.size(); ++j) s << "---|";
    s << "\n";
    for (const FittedMeasurement& m : out.measurements) {
        s << "| " << m.measurement.mode.text() << " (" << m.measurement.case_file << ") |";
        for (double v : m.dlnf_dlnp) s << " " << significant(v, 3) << " |";
        s << "\n";
    }
    s << "\n## Correlations of the fitted ln p\n\n|  |";
    for (const FitParameter& p : out.parameters) s << " `" << p.key << "` |";
    s << "\n|---|";
    for (size_t j = 0; j < out.parameters.size(); ++j) s << "---|";
    s << "\n";
    for (size_t j = 0; j < out.parameters.size(); ++j) {
        s << "| `" << out.parameters[j].key << "` |";
        for (size_t k = 0; k < out.parameters.size(); ++k)
            s << " " << significant(out.correlation(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k)), 3) << " |";
        s << "\n";
    }
    s << "\n## Calibrated case files\n\n";
    for (const std::string& f : calibrated_files) s << "- `" << f << "` (ready for `coremodal run` and `study`)\n";
    return s.str();
}

std::string fit_console(const FitOutcome& out) {
    std::ostringstream s;
    for (const FitParameter& p : out.parameters)
        s << "  " << p.key << " = " << quantity_text(p.value, p.dimension) << " ± " << uncertainty_text(p)
          << (p.at_bound ? " (at bound)" : "") << "\n";
    for (const std::string& w : out.warnings) s << "  warning: " << w << "\n";
    return s.str();
}

std::vector<std::string> write_fitted_cases(const std::filesystem::path& folder, const FitOutcome& outcome) {
    std::vector<std::string> files;
    for (const FittedCase& c : outcome.cases) {
        const std::string stem = std::filesystem::path(c.case_file).stem().string();
        std::string name = stem + "-fitted.toml";
        if (std::find(files.begin(), files.end(), name) != files.end()) name = stem + "-" + c.model + "-fitted.toml";
        write_text_file(folder / name, c.calibrated_text);
        files.push_back(name);
    }
    return files;
}

}  // namespace coremodal
