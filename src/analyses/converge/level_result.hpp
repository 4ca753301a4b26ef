// One level of a converge ladder after its repeated runs (what one run
// gives back: LevelRun, models/ladder/model_ladder.hpp): median timings, the largest peak memory.
#pragma once

#include "models/ladder/model_ladder.hpp"

#include <vector>

namespace coremodal {

// A level after its repeated runs: medians of the timings, the largest peak.
struct LevelResult {
    MeshStep step;
    long n_dofs = 0;
    int runs = 0;
    Timing median_s;
    double median_cpu_s = 0;
    SolverBreakdown median_solver_s;
    double peak_memory_mb = 0;
    std::vector<Mode> modes;  // of the first run (every run solves the same mesh)
    bool complete = true;
    double max_repeat_spread = 0;  // largest relative frequency difference between runs
};

LevelResult summarize_runs(const MeshStep& step, const std::vector<LevelRun>& runs);

}  // namespace coremodal
