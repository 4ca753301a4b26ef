// The results of `coremodal winder` (docs/how-to/winder.md): tables for programs
// (winder.csv, crossings.csv, response.csv, summary.json) and report.md for
// people, written into a results folder; the crossing diagram comes from
// `python3 -m coremodal winder-plot` (output/python_plots.hpp).
#pragma once

#include "winder/winder_sweep.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

// winder.csv: every reported mode at every diameter (type, shares, damping,
// track); crossings.csv; response.csv (|X/F| at each harmonic and diameter);
// summary.json (the resolved scene, the defaults in use, per diameter the
// nips, the estimate against the model and the verification; the crossings).
void write_winder_tables(const std::filesystem::path& dir, const WinderScene& scene, const WinderSweepResult& result);

// The resolved scene in SI units (TOML, the keys of summary.json's
// "scene") and the defaults it took: what `coremodal check` prints.
std::string winder_scene_description(const WinderScene& scene);

// report.md: the scene, the nips, the drum frequency against the estimate,
// the crossing diagram and its table, the response, the checks. `pngs` are
// the pictures drawn (file names in dir); `plot_problem` says why there are
// none ("" when drawn).
std::string winder_report_markdown(const WinderScene& scene, const WinderSweepResult& result,
                                   const std::vector<std::string>& pngs, const std::string& plot_problem);

// The lines the command prints: the crossings, the largest response, where
// the results are.
std::string winder_console_summary(const WinderScene& scene, const WinderSweepResult& result);

}  // namespace coremodal
