// The winder as the rolls grow: the modes at every roll diameter of the
// sweep, followed from diameter to diameter by MAC (modes/tracking), the roll
// rotation harmonics f_k = k v / (pi d), their crossings with the
// drum-dominated frequencies, and the response X/F at a drum's centre
// (docs/how-to/winder.md, "The crossing diagram").
#pragma once

#include "winder/winder_estimate.hpp"
#include "winder/winder_modes.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace coremodal {

// The k-th rotation harmonic of a roll of diameter d at web speed v, Hz.
double roll_harmonic_hz(int k, double web_speed, double roll_diameter);

struct SweepMode {
    int index = 0;  // 1-based at its diameter
    double frequency_hz = 0;
    BodyKind type = BodyKind::drum;
    std::array<double, kBodyKinds> kinetic_share{};
    double damping_ratio = 0;
    int track = 0;
    std::optional<double> mac_previous;
    bool ambiguous = false;
};

struct SweepPoint {
    double roll_diameter = 0;  // m
    WinderState state;
    std::vector<SweepMode> modes;           // the reported ones
    Verification verification;
    DrumFrequencyEstimate estimate;
    std::vector<double> harmonic_response;  // |X/F| (m/N) at f_k, k = 1..harmonics
};

// One track's frequency at every point (nullopt where the track is absent)
// and whether it is drum-dominated there: what the crossing search reads.
struct TrackSeries {
    int track = 0;
    std::vector<std::optional<double>> frequency_hz;
    std::vector<bool> drum;
};

struct Crossing {
    double roll_diameter = 0;  // m
    double frequency_hz = 0;   // of the harmonic there
    int harmonic = 0;
    int track = 0;
    // Filled by the sweep (a solve at the crossing diameter):
    double mode_frequency_hz = 0;  // the tracked mode's frequency at that diameter
    BodyKind type = BodyKind::drum;
    double damping_ratio = 0;
    double resonance_response = 0;  // |X/F| (m/N) at the drum's centre at the mode's frequency
};

// Where the harmonics cross the drum-dominated tracks: between two
// neighbouring diameters where track - harmonic changes sign and the track is
// drum-dominated at one of them at least. Both curves are interpolated
// linearly in 1/d, in which the harmonics are straight lines: a crossing with
// a track that is constant or linear in 1/d is found exactly.
std::vector<Crossing> find_crossings(const std::vector<double>& roll_diameters, const std::vector<TrackSeries>& tracks,
                                     double web_speed, int harmonics);

struct WinderSweepResult {
    std::vector<SweepPoint> points;
    std::vector<Crossing> crossings;
    int response_dof = 0;
    int n_dofs = 0;  // of the reduced model (the same at every diameter)
    double time_s = 0;
};

// progress(i, n) after each point (may be empty).
WinderSweepResult run_winder_sweep(const WinderScene& scene, const std::function<void(int, int)>& progress = {});

// The roll diameters of the sweep: start to end in `points` even steps.
std::vector<double> sweep_diameters(const WinderScene& scene);

}  // namespace coremodal
