// `coremodal durability`'s numbers, step by step as M. Ilomäki, "On the
// durability of cores and rest roll dynamics" takes them ({16}–{32}): the
// fit, the confidence, each failure probability's reduced curve, the table
// of allowed weights at 0.5, 1, 2, 5, 10, ... cycles and the curves of the
// plot (Figs. 16–17). Plain numbers; the writers are in output/.
#pragma once

#include "durability/durability_data.hpp"
#include "durability/durability_limits.hpp"
#include "durability/power_law_fit.hpp"

#include <vector>

namespace coremodal {

struct ProbabilityLimit {
    double probability = 0;  // P of {27}
    SafetyFactors factors;   // λ, S_C and the safety factors
    std::vector<double> allowed_weights;  // at DurabilityAnalysis::table_cycles, in the data's unit
};

struct DurabilityAnalysis {
    PowerLawFit fit;
    double confidence = kDefaultConfidence;
    double t2 = 0;            // {23}, n - 2 degrees of freedom
    double h1 = 0;            // {26}
    double upper_sd_log = 0;  // S_C of {25}
    ParameterIntervals intervals;  // two-sided at the confidence
    std::vector<ProbabilityLimit> limits;
    std::vector<double> table_cycles;  // 0.5, 1, 2, 5, 10, ... to past the data
    // The plot's curves on a log grid from 0.5 cycles to past the data:
    // fit, confidence and prediction bands, reduced curves (log10 y).
    std::vector<double> curve_cycles;
};

// The cycle counts of the table: 0.5, then 1, 2, 5, 10, 20, 50, ... up to
// the first at or above the most cycles in the data (at least 10).
std::vector<double> table_cycle_counts(double max_cycles);

// Every step for `data` at `confidence` for each failure probability in
// (0, 0.5] (the caller checks both).
DurabilityAnalysis analyse_durability(const DurabilityData& data, double confidence,
                                      const std::vector<double>& probabilities);

}  // namespace coremodal
