// A Campbell diagram of a spinning scene ([rotation], docs/theory/rotation.md)
// at any level that spins it: the level hands out its spinning model
// (ModelLevel::spinning, models/spinning_model.hpp: the beam's, the
// harmonic level's, the solid's), and the sweep here takes the modes at
// every speed, follows them from speed to speed by MAC, labels them
// forward/backward whirl, and finds the critical speeds where an excitation
// line f = k f_rot crosses a natural frequency.
//
// The sweep starts at rest: speed 0 is the level's solve at rest (at the
// beam level the very modes `run` reports; at the harmonic and solid levels
// the quadratic solver at speed 0, the level's modes), and a sweep or single
// speed above 0 is reached by continuation from it (kContinuationSteps
// speeds in between when the scene's first speed is above 0), so that every
// mode keeps the label it has at rest and a crossing of two curves does not
// swap them.
#pragma once

#include "beam/speeds.hpp"
#include "models/spinning_model.hpp"
#include "modes/rotating_mode.hpp"
#include "scene/response_spec.hpp"  // DampingSpec
#include "scene/rotation_spec.hpp"
#include "scene/scene.hpp"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// Continuation from rest to a scene's first speed above 0.
constexpr int kContinuationSteps = 8;
// Modes followed beyond the ones reported, so that a backward whirl coming
// down from above the window enters it on its own track.
constexpr int kExtraTrackedModes = 8;

struct CampbellMode {
    int track = 0;  // the same physical mode at every speed
    double frequency_hz = 0;
    Whirl whirl = Whirl::none;  // at rest: the whirl its track takes when spinning
    ModeLabel label;            // the track's label at rest
    double relative_residual = 0;
    // With [damping] (CampbellResult::damped): the damped mode that continues
    // this one (largest MAC of its wave number, at least kSameModeMac), its
    // ratio zeta = -Re lambda / |lambda| and damped frequency Im lambda / 2 pi;
    // none for a rigid mode (no damped partner above the rigid line).
    std::optional<double> damping_ratio, damped_frequency_hz;
};

struct CampbellPoint {
    double speed_hz = 0;  // f_rot
    std::vector<CampbellMode> modes;  // the lowest ones, as many as at rest
};

// Critical speeds are refined until the bracket [low, high] of f_rot that
// holds the root of f_track(f_rot) - k f_rot is this narrow relative to it.
constexpr double kCrossingSpeedTolerance = 1e-6;
// Solves per crossing at most (a smooth f_track needs 4 to 8).
constexpr int kMaxRefinementSolves = 30;

// A crossing of the excitation line f = order * f_rot with a tracked
// natural frequency: found between two speeds of the sweep (low, high),
// then refined by solving at speeds inside that bracket (run_campbell:
// regula falsi with the Illinois modification on g = f_track - order f_rot,
// the track followed by MAC from the bracket's ends) until the bracket is
// narrower than kCrossingSpeedTolerance relative to the speed.
// Where a crossing comes from: the sweep (bracketed between two speeds,
// then refined or interpolated), or, in co-rotating coordinates, the
// pencil of the speeds of zero rotating-frame frequency (exact; no track).
enum class CrossingSource { sweep, pencil };

struct WhirlCrossing {
    int order = 1;
    int track = 0;
    Whirl whirl = Whirl::none;
    ModeLabel label;
    double speed_hz = 0;      // f_rot at the crossing
    double frequency_hz = 0;  // = order * speed_hz
    double web_speed_m_s = 0; // pi Dp f_rot
    double low_speed_hz = 0, high_speed_hz = 0;  // the bracket: the sweep's speeds, or refined
    double interpolated_speed_hz = 0;            // linear interpolation between the sweep's two speeds
    bool refined = false;     // false: the interpolation (the track was lost inside the bracket)
    int refinement_solves = 0;
    CrossingSource source = CrossingSource::sweep;  // pencil: track 0, bracket and interpolation = speed_hz
};

// "sweep" or "pencil", as the tables write it.
const char* crossing_source_name(CrossingSource s);

struct CampbellResult {
    std::vector<CampbellPoint> points;       // the scene's speeds, ascending
    std::vector<WhirlCrossing> critical;     // ascending speed
    std::vector<int> excitation_orders;
    double roll_outer_diameter = 0;          // m, Dp
    bool from_web_speed = false;
    ModelChoice level = ModelChoice::beam;   // the model level (the writers say its word)
    std::string solver;                      // how each speed was solved, in words
    std::string completeness;                // why no mode is missed, in words
    RollSpeeds speeds_at_rest;               // I-5 safe web speed from the first bending frequency at rest
    double max_relative_residual = 0;        // of the quadratic problem, every mode at every speed
    long n_dofs = 0;
    double solve_seconds = 0;
    std::vector<std::string> effects;        // the terms included
    std::vector<std::string> notes;          // what is included and what is not
    std::string sweep_end;                   // where the sweep stopped short of the scene's speeds, and why; or empty
    std::optional<std::array<double, 2>> operating_hz;  // [rotation] operating_speeds, Hz; or none
    // [damping]: the modes' damping ratios were computed (campbell.csv's
    // damping_ratio and damped_frequency_hz columns; the critical speeds stay
    // the undamped sweep's); which damping entered, from which keys; the
    // largest relative residual of a damped mode on the full damped set.
    bool damped = false;
    std::vector<std::string> damping;
    double max_damped_residual = 0;
    // The first order-1 crossing, if any.
    const WhirlCrossing* first_order_one() const;
    // The critical speeds inside the operating range (ends included); none without one.
    std::vector<const WhirlCrossing*> inside_operating_range() const;
};

// Throws InputError when the scene's level (with "auto" resolved) cannot
// spin it: not beam, harmonic or solid, or a solid scene that is not a body
// of revolution (models/solid/rotating_solid.hpp). Before any work.
void require_spinning_level(const Scene& scene);

// Throws InputError when [damping] cannot enter the sweep: at a level whose
// operator sets do not carry it (only the harmonic level's do), or in a form
// that is not a term of the operators (a modal ratio: ratio, log_decrement,
// decay, a family's or a mode's own; effects/damping.hpp's operator_damping_of
// says which are). Before any work.
void require_campbell_damping(const Scene& scene, const DampingSpec& damping);

// Throws InputError as require_spinning_level and require_campbell_damping
// (the scene's model resolved already); SolveError from the solver. With
// `damping`, every reported mode also gets its damping ratio (CampbellMode).
CampbellResult run_campbell(const Scene& scene, const RotationSpec& rotation, const DampingSpec* damping = nullptr);

// Crossings of f = order f_rot with every track of `points`, by linear
// interpolation between two speeds (run_campbell refines them).
std::vector<WhirlCrossing> critical_speeds(const std::vector<CampbellPoint>& points, const std::vector<int>& orders,
                                           double roll_outer_diameter);

// run_campbell's sweep on any level's modes (tests): from the modes at rest
// over rotation.speeds_hz, tracked by MAC; fills out.points and
// out.critical (refined), out.excitation_orders and out.roll_outer_diameter
// set by the caller. With `label_new_track` the modes of modes_at need no
// label: only a mode that starts a track is labelled. With `block_modes_at`
// a crossing's refinement solves only its track's block. With `damped_partners`
// every reported mode gets its damping ratio (the crossings stay undamped).
void campbell_sweep(const std::vector<RotatingMode>& at_rest, size_t reported, const ModesAtSpeed& modes_at,
                    const RotationSpec& rotation, CampbellResult& out, const LabelMode& label_new_track = {},
                    const BlockModesAtSpeed& block_modes_at = {}, const DampedPartners& damped_partners = {});

}  // namespace coremodal
