// `coremodal beam`'s output: the text report and the one JSON object (--json).
#pragma once

#include "analyses/formulas/beam_formulas.hpp"

#include <ostream>

namespace coremodal {

void print_beam_formulas_text(const BeamFormulas& formulas, std::ostream& out);
// The JSON of `beam --json`: the head and I-5 shape of every summary.json;
// seconds: the time the formulas took (timing_s.total).
void print_beam_formulas_json(const BeamFormulas& formulas, double seconds, std::ostream& out);

}  // namespace coremodal
