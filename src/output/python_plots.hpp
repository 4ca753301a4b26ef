// The pictures of a results folder come from the python package in python/
// (matplotlib); the numbers never depend on it. Every command that draws
// (run, study, calibrate, converge) starts it through run_python_plot.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

// The interpreter: $COREMODAL_PYTHON if set and not empty, else the one CMake
// was configured with (COREMODAL_PYTHON, Debian's /usr/bin/python3, which has
// numpy, h5py and matplotlib). A bare name is looked up on the PATH.
std::string python_interpreter();

// Runs `PYTHON -m coremodal SUBCOMMAND FOLDER ARGS...` with the python
// package first on PYTHONPATH — $COREMODAL_PYTHON_DIR if set, else the
// installed package beside an installed program (PREFIX/share/coremodal/
// python, see CMakeLists.txt), else this source tree's python/ — and
// MPLBACKEND=Agg, and waits for it. Its output
// goes to FOLDER/plot.log, which is removed when it succeeds.
// Returns "" on success, else why there are no pictures, in words for a
// report ("/nonexistent -m coremodal run-plot could not start: No such file
// or directory"); never throws for a failed plot.
std::string run_python_plot(const std::string& subcommand, const std::filesystem::path& folder,
                            const std::vector<std::string>& args = {});

// The pictures of a command that draws them all with one plot command
// (campbell, response, winder): `pngs` when drawn, else none and why
// ("switched off (--no-plots)" or the plot's failure, which is also said on
// stderr as a warning: the tables and report.md are complete without them).
struct Pictures {
    std::vector<std::string> pngs;
    std::string problem;
};
Pictures draw_pictures(const std::string& subcommand, const std::filesystem::path& folder, bool no_plots,
                       const std::vector<std::string>& pngs);

}  // namespace coremodal
