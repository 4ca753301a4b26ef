// `coremodal beam`'s output: the text report and the one JSON object (--json).
#pragma once

#include "analyses/formulas/beam_formulas.hpp"

#include <ostream>

namespace coremodal {

void print_beam_formulas_text(const BeamFormulas& formulas, std::ostream& out);
void print_beam_formulas_json(const BeamFormulas& formulas, std::ostream& out);

}  // namespace coremodal
