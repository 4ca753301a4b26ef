// Following the same physical mode from one study point to the next by the
// modal assurance criterion (mac.hpp), so that a curve stays on one mode where
// modes cross in frequency.
//
// 1. The modes of a point are grouped: a degenerate pair (bending, ovalling:
//    any rotation of a member is a mode too) is one group, a subspace; all
//    rigid-body modes are one group.
// 2. Between a point and its predecessor, every pair of groups gets a MAC
//    (subspace_mac; the labels when a model gives no signatures).
// 3. Groups are assigned to the predecessor's tracks so that the total MAC is
//    largest (Hungarian algorithm). A match below kNewTrackMac is no match: the
//    group starts a new track (a mode entering the window of the lowest modes)
//    and the old track ends there.
// 4. A step is ambiguous when the match is below kAmbiguousMac, or when
//    another candidate comes within kCloseCandidateMac of it.
#pragma once

#include "eigensolve/tolerances.hpp"
#include "modes/mac.hpp"
#include "modes/mode_set.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// Modes closer than kDegenerateGap (eigensolve/tolerances.hpp) are one
// degenerate group.
// Two neighbouring modes with the same label (type, n >= 1, m) closer than
// this are one pair even so: a mesh without rotational symmetry (tetrahedra)
// splits a pair by up to ~1e-3.
constexpr double kSplitPairGap = 1e-2;
// Below this MAC a match is not the same mode.
constexpr double kNewTrackMac = 0.5;
// Below this MAC, or with a rival candidate this close, a match is ambiguous.
constexpr double kAmbiguousMac = 0.8;
constexpr double kCloseCandidateMac = 0.1;

// What tracking needs of one mode: a run's Mode without its (large) shape.
struct ModeSummary {
    int index = 0;  // 1-based, as in the run
    double frequency_hz = 0;
    ModeLabel label;
    Signature signature;  // empty when the model gave none
};

// One group of modes of a point: a single mode, a degenerate pair, or all rigid modes.
struct ModeGroup {
    std::vector<int> members;  // positions in the point's mode list
    double frequency_hz = 0;   // of the first member
    ModeLabel label;           // of the first member
    std::vector<Signature> signatures;
};

// "bending n=1 m=0"; "rigid".
std::string label_text(const ModeLabel& label);

std::vector<ModeGroup> group_modes(const std::vector<ModeSummary>& modes);

// MAC of two groups: subspace_mac of their signatures, or, when either has
// none, 1 for equal labels (type, n, m) and 0 otherwise.
double group_mac(const ModeGroup& a, const ModeGroup& b);

// Maximum-weight assignment of rows to columns (Hungarian algorithm on a
// rectangular matrix): result[row] = column or -1 (more rows than columns).
std::vector<int> assign_maximum(const std::vector<std::vector<double>>& weight);

struct TrackStep {
    int track = 0;                       // track id of each group of the new point
    std::optional<double> mac_previous;  // MAC to the matched group of the predecessor
    bool ambiguous = false;
    bool new_track = false;              // no predecessor group matched
};

// Tracks of the groups of `current`, given the groups of the predecessor and
// their tracks. New tracks take ids from next_track_id (which is advanced).
std::vector<TrackStep> follow_tracks(const std::vector<ModeGroup>& previous, const std::vector<int>& previous_tracks,
                                     const std::vector<ModeGroup>& current, int& next_track_id);

// Tracks of the first point: 1, 2, ... in frequency order.
std::vector<TrackStep> start_tracks(const std::vector<ModeGroup>& groups, int& next_track_id);

}  // namespace coremodal
