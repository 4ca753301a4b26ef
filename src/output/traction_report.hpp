// The results of `coremodal traction` (docs/how-to/traction.md): traction.csv and
// summary.json for programs, report.md for people; traction.png comes from
// `python3 -m coremodal traction-plot` (output/python_plots.hpp).
#pragma once

#include "scene/traction_case.hpp"
#include "traction/traction_sweep.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

// traction.csv: per web speed the tension, air, wrap and contact pressures,
// P*, h*, theta*, B*, the traction and effective friction (and the plain
// roller's beside a grooved one), whether the point is valid and why not;
// summary.json: the inputs in SI, the clearance, the speeds, the validity
// limits, the assumptions and every point.
// `seconds`: the command's wall time so far (summary.json timing_s.total).
void write_traction_tables(const std::filesystem::path& dir, const TractionCase& tc, const TractionSweep& sweep,
                           double seconds);

// report.md: the roller, the clearance, the speeds, the curve in a table,
// the validity limits, the assumptions; `pngs` the pictures drawn (file
// names in dir), `plot_problem` why there are none ("" when drawn).
std::string traction_report_markdown(const TractionCase& tc, const TractionSweep& sweep,
                                     const std::vector<std::string>& pngs, const std::string& plot_problem);

// What `coremodal check` says of a [traction] table: the resolved roller and
// web (SI), the clearance and the zero-traction speed, the defaults used.
std::string traction_check_text(const TractionCase& tc);

// The lines the command prints.
std::string traction_console_summary(const TractionCase& tc, const TractionSweep& sweep);

}  // namespace coremodal
