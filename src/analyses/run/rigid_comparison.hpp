// Rigid against elastic chucks, as König compared them: the scene is run a
// second time with each chuck replaced by a rigid clamp over the span of its
// expanding elements, and the modes of the two runs are paired by type, n
// and order (the k-th bending mode with the k-th), with the frequency shift.
#pragma once

#include "results/run_report.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The scene with rigid clamps from the innermost to the outermost edge of
// each chuck's expanding elements (no chucks, shafts or bearings).
Scene rigid_clamp_variant(const Scene& scene);

// Pairs modes by type, n and order; a degenerate pair stays two rows. Modes without a
// partner get a row with the other side's index 0.
std::vector<ModeShift> pair_by_label(const std::vector<Mode>& elastic, const std::vector<Mode>& rigid);

}  // namespace coremodal
