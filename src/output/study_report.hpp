// What `coremodal study` (and `calibrate`) write: study.csv (one row per
// point and tracked mode group), study.json (the sweep, for the plotting
// script), the PNGs (python: study-plot) and report.md. study_tables.cpp
// holds the tables and the files, study_markdown.cpp the report.
#pragma once

#include "analyses/study/study.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

// The column of a parameter in study.csv: its name and SI unit ("core.length_m").
std::string parameter_column(const SweepParameter& p);

// One row per point and tracked mode group; a failed point has one row with its error.
std::string study_csv(const CaseSweep& sweep, const StudyResult& result);
// Metadata for the plotting script (python/coremodal/study_plot.py).
std::string study_json(const CaseSweep& sweep, const StudyResult& result, const std::string& kind);

// Writes study.csv and study.json into `dir` and, with `plots`, the PNGs;
// returns the PNG file names found in `dir` afterwards and, if the plots
// could not be drawn, why.
struct StudyFiles {
    std::vector<std::string> pngs;
    std::string plot_problem;
};
StudyFiles write_study_files(const std::filesystem::path& dir, const CaseSweep& sweep, const StudyResult& result,
                             const std::string& kind, bool plots);

std::string study_report_markdown(const CaseSweep& sweep, const StudyResult& result,
                                  const std::vector<std::string>& pngs, const std::string& plot_problem);

// With [study] web_speed: per curve, the diameter below which the roll must
// be changed at that speed ("  at 15 m/s: Do 106: change the roll below
// D = 412 mm"); "" without it.
std::string study_crossings_console(const CaseSweep& sweep, const StudyResult& result);

}  // namespace coremodal
