// report.md of a run: what a person reads after `coremodal run` — the scene,
// the model, the verification, the mode table, beam theory beside the FE
// result, the chuck factor k, the safe web speed and König's critical speed,
// the pictures, timings and warnings. Every number is one the run computed
// (RunReport) or one of the quick formulas of beam/formulas.hpp applied to it.
#pragma once

#include "output/run_pictures.hpp"
#include "output/run_report.hpp"

#include <string>

namespace coremodal {

// The safety factors of the safe web speed in the report (I-5): Ilomäki's
// range, 0.7 without a safety cage, at most 0.8.
constexpr double kReportSafeFactors[] = {0.7, 0.8};

std::string run_report_markdown(const RunReport& report, const RunPictures& pictures);

}  // namespace coremodal
