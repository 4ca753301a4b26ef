// report.md of a run: what a person reads after `coremodal run` — the scene,
// the model, the verification, the mode table, beam theory beside the FE
// result, the chuck factor k, the safe web speed and König's critical speed,
// the pictures, timings and warnings. Every number is one the run computed
// (RunReport) or one of the quick formulas of beam/formulas.hpp applied to it.
#pragma once

#include "output/run_pictures.hpp"
#include "results/run_report.hpp"

#include <string>

namespace coremodal {

std::string run_report_markdown(const RunReport& report, const RunPictures& pictures);

}  // namespace coremodal
