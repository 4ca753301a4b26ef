// The roll free over its free span: the scene's core and rest paper cut to
// L = Lc - (Li,left + Li,right) (Ilomäki I-6, I-7; docs/theory/chucks.md),
// with nothing holding it: no chucks, stands or bearings, and no
// paper web. The chuck factor k = f1 / f2 compares the roll in its stand
// with this roll (`run`, analyses/run/beam_comparison.cpp), and `sensitivity`
// differentiates k through it (analyses/sensitivity): both derive it here.
#pragma once

#include "scene/scene.hpp"

namespace coremodal {

// The free–free roll over the scene's free span, solved for its first
// `n_modes` modes (6 rigid modes and the first bending pair: 8), with the
// scene's mesh counts (the ladder's per-segment counts cleared: they are for
// the scene's segments, not the span's) and the default analysis otherwise.
Scene free_span_scene(const Scene& scene, int n_modes);

}  // namespace coremodal
