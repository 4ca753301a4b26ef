// Step 8 of `coremodal run`: what the run hands its writer (RunWriter,
// analyses/run/run.hpp) is printed and written here, so that the run itself
// writes nothing and output/ stays above analyses/.
#pragma once

#include "analyses/run/run.hpp"
#include "models/model_level.hpp"

namespace coremodal {

// Rank 0: the console tables unless options.quiet, then, unless
// !options.write_results, the results folder (run_folder: complete or not at
// all) with the level's mode shapes.
void write_run(const RunReport& report, const ModelLevel& level, const RunOptions& options);

}  // namespace coremodal
