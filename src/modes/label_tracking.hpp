// Following modes across runs of the same scene on different meshes by their
// labels (type, n, m): the modes of a refinement ladder (coremodal converge).
// A label and its occurrence name the same mode on every mesh and in every
// model level (solid, harmonic, beam), which converge's roles and model
// errors need. The points of `coremodal study` change the scene, and there
// modes are followed by MAC (tracking.hpp).
//
// 1. The modes of a run are reduced to distinct modes: degenerate partners
//    (bending pairs, ovalling pairs) are one mode, rigid and mixed modes are
//    left out (a mixed label cannot be matched across meshes).
// 2. A distinct mode is identified by its label and which occurrence of that
//    label it is (1 = the lowest): ModeKey.
// 3. Tracks are the keys found at every run, plus the role modes (the first
//    distinct mode of a type at the last run) even where a run lacks them.
#pragma once

#include "eigensolve/tolerances.hpp"
#include "modes/mode_set.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace coremodal {

// A mode's identity across meshes: its label and which occurrence of that
// label it is (1 = the lowest). Degenerate partners (bending pairs, ovalling
// pairs) are one tracked mode.
struct ModeKey {
    std::string type;
    int n = 0, m = 0;
    int occurrence = 1;
    bool operator==(const ModeKey&) const = default;
    std::string text() const;  // "bending n=1 m=0" (+ " #2" for a second occurrence)
};

// Partners with the same label closer than kDegenerateTolerance
// (eigensolve/tolerances.hpp) are one mode.

struct DistinctMode {
    ModeKey key;
    double frequency_hz = 0;
    int index = 0;         // 1-based index of the first partner in the run
    int multiplicity = 1;  // 2 for a degenerate pair
};

// Distinct elastic modes of one run: rigid and mixed modes are left out.
std::vector<DistinctMode> distinct_modes(const std::vector<Mode>& modes);

// Whether a run has a distinct mode of this type ("ovalling", "torsion", ...).
bool has_mode_type(const std::vector<Mode>& modes, const std::string& type);

// A role: a name for the first distinct mode of a type ("f1" for "bending").
using ModeRole = std::pair<std::string, std::string>;  // name, type

// One mode followed across runs.
struct LabelTrack {
    ModeKey key;
    std::string role;                                 // a role name, or "" (tracked, no role)
    std::vector<std::optional<double>> frequency_hz;  // per run; empty where the key is missing
};

// Tracks over runs (coarse to fine), each given by its distinct modes: every
// key present at every run, plus each role's mode of the last run even if an
// earlier run lacks it; in the last run's frequency order.
std::vector<LabelTrack> track_by_label(const std::vector<std::vector<DistinctMode>>& runs,
                                       const std::vector<ModeRole>& roles);

}  // namespace coremodal
