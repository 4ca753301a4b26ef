// Writers of the human- and machine-readable summaries of a run:
// console table, summary.json (schema in docs/reference/results.md), modes.csv.
#pragma once

#include "results/run_report.hpp"

#include <iosfwd>
#include <string>

namespace coremodal {

// The resolved scene (SI units) as JSON text, also stored in modes.h5.
std::string scene_json(const Scene& scene);

void write_summary_json(const std::string& path, const RunReport& report);
void write_modes_csv(const std::string& path, const RunReport& report);
void print_mode_table(std::ostream& out, const RunReport& report);
void print_verification_and_beam(std::ostream& out, const RunReport& report);

}  // namespace coremodal
