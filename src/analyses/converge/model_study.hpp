// What the levels of one model level say: its modes tracked across the
// levels by label (modes/label_tracking.hpp), their extrapolated frequencies
// (numerics/richardson.hpp), how time and memory grow with the DOFs, and
// which level reaches an accuracy target or where the ladder would have to go.
#pragma once

#include "analyses/converge/level_result.hpp"
#include "modes/label_tracking.hpp"
#include "numerics/richardson.hpp"
#include "scene/model_choice.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace coremodal {

// The roles the study reports on: the first bending mode f1, the first
// ovalling mode, the first torsion, axial and breathing modes.
inline const std::vector<ModeRole> kModeRoles = {
    {"f1", "bending"}, {"ovalling", "ovalling"}, {"torsion", "torsion"}, {"axial", "axial"},
    {"breathing", "breathing"}};

struct TrackedMode {
    ModeKey key;
    std::string role;                               // "f1", "ovalling", ... or "" (tracked, no role)
    std::vector<std::optional<double>> frequency_hz;  // per level; empty when the label is missing
    std::optional<Richardson> richardson;           // when the three finest levels have it
    std::vector<std::optional<double>> relative_error;  // |f - f0| / f0 per level
};

// Modes tracked across levels: every label present at every level, plus the
// role modes (labels taken from the finest level) even if a coarser level
// lacks them. Sorted by the finest level's frequency.
std::vector<TrackedMode> track_modes(const std::vector<LevelResult>& levels);

// What a converge study says of a model level's ladder beyond its numbers:
// set by the level's ladder (model_ladder.cpp, from scene/level_traits.hpp
// and the ladder's own words) and read by the writers (output/converge_*).
struct LadderTraits {
    bool reference = false;     // the solid: the others' model error is measured against it
    bool meshed = true;         // a mesh ladder (not the beam network): its timing columns, a shared mode count
    bool same_section = false;  // the harmonic: the reference's own r-z section, so a difference is its error
    std::string timing_parts;   // what the timing columns mean, where not a meshed solid's ("" there)
    std::string cost_note;      // the paragraph before the cost of the finest level, or ""
};

// All levels of one model level ("solid", "beam", "harmonic") and what they say.
struct ModelStudy {
    std::string model;
    LadderTraits traits;
    std::string ladder_note;  // how the ladder was built, for the report
    std::vector<LevelResult> levels;
    std::vector<TrackedMode> modes;
    std::optional<double> time_exponent;    // total time ~ DOFs^e (levels after the coarsest)
    std::optional<double> memory_exponent;  // peak memory ~ DOFs^e
    int n_modes = 0;                        // modes asked per run
    int refined_dimensions = 3;             // DOFs ~ k^this, for predict_level_for
    // Roles (kModeRoles) this model cannot have, and why (the beam: ovalling
    // and breathing, which deform the cross-section).
    std::vector<std::pair<std::string, std::string>> unseen_roles;
};

// A level's ladder traits, from what the level can do (scene/level_traits.hpp).
LadderTraits ladder_traits(ModelChoice level);

// The study of a level's ladder: its modes tracked, extrapolated, and the cost's scaling.
ModelStudy analyse_levels(ModelChoice level, std::string ladder_note, std::vector<LevelResult> levels);

// The tracked mode of a role, or nullptr.
const TrackedMode* find_role(const ModelStudy& model, const std::string& role);

// The accuracy targets of the report: 1 %, 0.1 %, 0.01 %.
inline const std::vector<double> kAccuracyTargets = {1e-2, 1e-3, 1e-4};

// The cheapest level whose error, plus the uncertainty of f0, is within the
// target; nullopt if none is.
std::optional<std::size_t> first_level_within(const TrackedMode& mode, double target);

// Where the ladder would have to go for a target it does not reach, from the
// observed order (error ~ (1/k)^p from the finest level), DOFs ~ k^d (d =
// ModelStudy::refined_dimensions: 3 for the solid, 1 for the beam) and the
// observed time exponent. Nothing when the mode is not asymptotic or when f0
// itself is not known to better than the target.
struct TargetPrediction {
    double k = 0;
    double n_dofs = 0;
    std::optional<double> time_s;
};
std::optional<TargetPrediction> predict_level_for(const ModelStudy& model, const TrackedMode& mode, double target);

}  // namespace coremodal
