#include "analyses/converge/level_result.hpp"

#include "common/error.hpp"
#include "numerics/median.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// The median over the runs of one field of a run.
template <typename Field>
double median_of(const std::vector<LevelRun>& runs, Field field) {
    std::vector<double> v;
    for (const auto& run : runs) v.push_back(field(run));
    return median(v);
}

Timing median_timing(const std::vector<LevelRun>& runs) {
    auto med = [&](double Timing::*part) {
        return median_of(runs, [part](const LevelRun& run) { return run.timing_s.*part; });
    };
    return {.mesh = med(&Timing::mesh),
            .assemble = med(&Timing::assemble),
            .factor_and_solve = med(&Timing::factor_and_solve),
            .classify = med(&Timing::classify),
            .chuck_factor = med(&Timing::chuck_factor),
            .total = med(&Timing::total)};
}

SolverBreakdown median_solver(const std::vector<LevelRun>& runs) {
    auto med = [&](double SolverBreakdown::*part) {
        return median_of(runs, [part](const LevelRun& run) { return run.solver_s.*part; });
    };
    return {med(&SolverBreakdown::factor_s), med(&SolverBreakdown::solve_s), med(&SolverBreakdown::orthogonalize_s)};
}

}  // namespace

LevelResult summarize_runs(const MeshStep& step, const std::vector<LevelRun>& runs) {
    COREMODAL_ASSERT(!runs.empty());
    LevelResult r;
    r.step = step;
    r.n_dofs = runs.front().n_dofs;
    r.runs = static_cast<int>(runs.size());
    r.modes = runs.front().modes;
    r.median_s = median_timing(runs);
    r.median_cpu_s = median_of(runs, [](const LevelRun& run) { return run.cpu_s; });
    r.median_solver_s = median_solver(runs);
    for (const auto& run : runs) {
        r.peak_memory_mb = std::max(r.peak_memory_mb, run.peak_memory_mb);
        r.complete = r.complete && run.complete;
        // Every run solves the same mesh: the frequencies must agree.
        for (std::size_t i = 0; i < std::min(run.modes.size(), r.modes.size()); ++i) {
            const double a = run.modes[i].frequency_hz, b = r.modes[i].frequency_hz;
            if (std::max(a, b) > 0) r.max_repeat_spread = std::max(r.max_repeat_spread, std::abs(a - b) / std::max(a, b));
        }
    }
    return r;
}

}  // namespace coremodal
