// One level of a converge ladder: what one run gives back, and the level
// after its repeated runs (median timings, the largest peak memory).
#pragma once

#include "analyses/converge/refinement_ladder.hpp"
#include "modes/mode_set.hpp"
#include "results/run_report.hpp"

#include <vector>

namespace coremodal {

// Where factor_and_solve goes, from PETSc's and SLEPc's event logs (seconds,
// rank 0): numeric and symbolic factorizations (the shift-and-invert
// Cholesky and the LDL^T of the inertia count), triangular solves, and the
// M-orthogonalization of the Krylov basis. The rest of factor_and_solve is
// the other Krylov-Schur work (M products, projected problem) and the
// residual and orthonormality checks. (Events are inclusive: the products of
// the shift-and-invert operator contain the solves, so they are not listed.)
struct SolverBreakdown {
    double factor_s = 0, solve_s = 0, orthogonalize_s = 0;
};

// What one run of one mesh level gives back (model-level independent).
struct LevelRun {
    long n_dofs = 0;
    Timing timing_s;
    SolverBreakdown solver_s;
    double cpu_s = 0;  // processor time of the run (user + system, this process, rank 0):
                       // on a shared machine less disturbed by other processes than wall time
    double peak_memory_mb = 0;
    std::vector<Mode> modes;  // frequency order; shapes not kept
    bool complete = true;     // the solver proved no mode missing
};

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
