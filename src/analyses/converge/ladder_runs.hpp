// Running the levels of a model ladder: how many modes a run asks for, the
// repeated runs of one level and their medians, and the named mesh levels
// (--check-levels) run once for comparison. Collective over PETSC_COMM_WORLD;
// progress lines on rank 0 unless quiet.
#pragma once

#include "analyses/converge/converge.hpp"
#include "analyses/converge/model_ladder.hpp"

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace coremodal {

// The study reports on the first ovalling mode, which beam theory cannot see;
// it often lies above the case's own request (case 03: mode 17). Doubles
// n_modes on the coarsest level (cheap) until an ovalling mode shows, up to
// kMaxModesForOvalling. Returns the last coarsest run, which counts as that
// level's first run; nothing when the count is given (--modes, a band).
std::optional<LevelRun> choose_mode_count(const Scene& scene, const ModelLadder& ladder, const ConvergeOptions& o,
                                          int& n_modes, std::ostream& progress, std::vector<std::string>& notes);

// Level i of the ladder: its runs (first_run, if given, counts as the first),
// repeated up to --repeats (or the ladder's runs_per_level) unless the first
// run took longer than --repeat-limit or the ladder's level budget is spent.
LevelResult run_level(const ModelLadder& ladder, std::size_t i, std::optional<LevelRun> first_run,
                      const ConvergeOptions& o, std::ostream& progress);

// A named mesh level ("coarse", "default", ...) run once by the reference
// ladder (the solid's, whose meshes the named levels are).
NamedLevelCheck run_named_level(const Scene& scene, const std::string& name, const ModelLadder& reference,
                                const ConvergeOptions& o, std::ostream& progress);

// Seconds in progress lines: `format` ("%.1f"), but two significant digits
// below 0.1 s (a beam run takes ~1e-3 s).
std::string progress_seconds(double s, const char* format);

}  // namespace coremodal
