// The whole converge study: every model level's ModelStudy, the named mesh
// levels checked against them, and the model error of the simpler levels
// against the solid's.
#pragma once

#include "analyses/converge/model_study.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// A named mesh level (--check-levels) run once and compared with the study's
// extrapolated values: how good is "default"?
struct NamedLevelCheck {
    std::string name;
    std::string mesh;  // wall/paper/around/along
    LevelResult result;
};

struct ConvergeStudy {
    std::string case_name, source_file;
    int n_modes = 0;           // modes asked per solid run (ModelStudy::n_modes per model level)
    int repeats = 0;           // runs per level asked (levels slower than repeat_limit_s run once)
    double repeat_limit_s = 0;
    std::vector<ModelStudy> models;
    std::vector<NamedLevelCheck> checks;  // solid model only
    std::vector<std::string> notes;
    double total_time_s = 0;
    double ladder_time_s = 0;  // the ladders alone (total less the named-level checks)
    // The machine's 1-minute load average at the start and the end: timings
    // on a shared machine include waiting for other processes.
    double load_start = 0, load_end = 0;
    int n_cores = 0;
};

// The study the others' model error is measured against (the solid's), or nullptr.
const ModelStudy* find_reference(const std::vector<ModelStudy>& models);

// A model level's converged value of a role against the solid's: the model
// error, which no refinement of the simpler model removes (a beam never
// converges to the 3D answer). For the harmonic level, which is exact in
// theta on the solid's own r-z section, the difference is instead the solid's
// circumferential discretization error left in its extrapolated f0 (the
// solid's ladder refines around together with the section), plus both
// extrapolations' noise.
struct ModelError {
    std::string model, role;
    std::string id, solid_id;  // the tracked modes' labels
    double f0_hz = 0, solid_f0_hz = 0;
    double relative = 0;        // (f0 - solid f0) / solid f0
    double known_to = 0;        // both extrapolations' error estimates and f0 uncertainties, relative
};

// For every model level other than the solid and every role both have
// extrapolated (kModeRoles order).
std::vector<ModelError> model_errors(const std::vector<ModelStudy>& models);

// |f - f0 of the solid's mode of the same role| / that f0, per level of a
// tracked mode of another model level; empty when the solid has no such f0.
std::vector<std::optional<double>> error_against_solid(const TrackedMode& mode, const std::vector<ModelStudy>& models);

}  // namespace coremodal
