// A level's model of a spinning scene ([rotation], docs/theory/rotation.md),
// for a Campbell sweep (analyses/campbell): its modes at rest and at any
// speed, and the capabilities a level may lack as empty members (a label
// for a new track, the modes of one independent problem, the damped
// partners, the pencils of co-rotating coordinates). The level hands it out
// (ModelLevel::spinning); the analysis sweeps, tracks and finds the critical
// speeds over it and never names a level. The beam's is in
// models/beam/beam_spinning.cpp, the harmonic level's in
// models/harmonic/harmonic_spinning.cpp, the solid's in
// models/solid/solid_spinning.cpp.
#pragma once

#include "common/error.hpp"
#include "modes/rotating_mode.hpp"
#include "scene/response_spec.hpp"  // DampingSpec
#include "scene/rotation_spec.hpp"
#include "scene/scene.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// A planar mode at rest has MAC 1/2 with each of the circular forward and
// backward modes it splits into; below this a match is another mode.
constexpr double kSameModeMac = 0.3;

// The modes of a spinning level at a speed (Hz), ascending, and a mode's label.
using ModesAtSpeed = std::function<std::vector<RotatingMode>(double speed_hz)>;
using LabelMode = std::function<ModeLabel(const RotatingMode&)>;
// The modes of one independent problem (RotatingMode::block) at a speed, for
// a level where solving one is cheaper than solving all (the harmonic level:
// one wave number).
using BlockModesAtSpeed = std::function<std::vector<RotatingMode>(double speed_hz, int block)>;
// The damped modes that continue `modes` (one speed's, as modes_at gives
// them), one per mode, or none where a mode has no damped partner.
struct DampedPartner {
    double damping_ratio = 0, damped_frequency_hz = 0, relative_residual = 0;
};
using DampedPartners =
    std::function<std::vector<std::optional<DampedPartner>>(double speed_hz, const std::vector<RotatingMode>& modes)>;

// A speed where a mode's rotating-frame frequency is r f_rot (co-rotating
// coordinates only; eigensolve/zero_frequency_speeds.hpp). Seen from the
// stationary frame the mode, of dominant signed harmonic k, has the
// frequency |r - k| f_rot (models/solid/rotating_frame.hpp): a crossing of
// the excitation line of order |r - k|, forward when -k (r - k) > 0.
// r = 0: the mode stands still on the spinning roll, a forward crossing of
// order |k| (k = 0: a static divergence).
struct ZeroFrequencyMode {
    double speed_hz = 0;  // f_rot
    int wave_number = 0;  // |k|
    int harmonic = 0;     // k, signed (r = 0: |k|, the null vector being real)
    int order = 0;        // |r - k|: f_stat / f_rot
    Whirl whirl = Whirl::none;
    // The dominant harmonic's energy share on the roll's surface (r = 0:
    // of +k and -k together, which carry equal energy in a real vector).
    double share = 1;
    ModeLabel label;
    int multiplicity = 1;  // equal speeds (a pair of a scene symmetric about z) counted once
    double relative_residual = 0;
};

struct ZeroFrequencyModes {
    std::vector<ZeroFrequencyMode> modes;  // ascending speed
    long counted = 0;                      // by inertia, multiplicity included (complex count for r > 0)
    double max_speed_hz = 0;
    int ratio = 0;  // r
};

// The exact critical speeds of a level in co-rotating coordinates
// (analyses/campbell/zero_frequency_crossings.hpp drives them).
class ZeroFrequencyPencils {
public:
    // Every speed below max_speed_hz where a mode's rotating-frame frequency
    // is zero, exact (the pencil (K, M_P - K_sigma1)) and proven complete by
    // the inertia of K(Omega_max).
    virtual ZeroFrequencyModes zero_frequency_modes(double max_speed_hz) const = 0;
    // The same for a rotating-frame frequency of r f_rot, r = ratio >= 0
    // (the pencil (K, B_r); r = 0 is zero_frequency_modes): each mode with
    // its signed harmonic, its crossing's order and whirl.
    virtual ZeroFrequencyModes frequency_ratio_modes(double max_speed_hz, int ratio) const = 0;

protected:
    ~ZeroFrequencyPencils() = default;
};

// What a sweep asks of a level's spinning model.
struct SpinningOptions {
    RotationSpec rotation;                 // the scene's speeds (the last one: the sweep's top) and terms
    int extra_tracked_modes = 0;           // solved at every speed beyond the reported ones
    const DampingSpec* damping = nullptr;  // [damping] as terms of the operators, or none
};

class SpinningModel {
public:
    virtual ~SpinningModel() = default;
    // The modes at rest, labelled, ascending (the level's own modes of the
    // scene), of which the first reported() are reported at every speed.
    virtual std::vector<RotatingMode> modes_at_rest() const = 0;
    virtual size_t reported() const = 0;
    // The lowest modes at spin speed f_rot (Hz), the reported ones and
    // SpinningOptions::extra_tracked_modes more, ascending.
    virtual std::vector<RotatingMode> modes_at(double speed_hz) const = 0;
    // Empty where modes_at labels every mode; else the label of a mode that
    // starts a track (labelling every mode at every speed costs more).
    virtual LabelMode label_new_track() const { return {}; }
    // Empty where one independent problem is no cheaper to solve than all.
    virtual BlockModesAtSpeed block_modes_at() const { return {}; }
    // Empty without SpinningOptions::damping.
    virtual DampedPartners damped_partners() const { return {}; }
    // None in the stationary frame.
    virtual const ZeroFrequencyPencils* zero_frequency_pencils() const { return nullptr; }
    virtual long n_dofs() const = 0;
    // What is included and what is not (before the sweep), and what the
    // sweep found out about the model (after it).
    virtual std::vector<std::string> notes() const = 0;
    virtual std::vector<std::string> notes_after_sweep() const { return {}; }
    // How each speed was solved and why no mode is missed, in words (after
    // the sweep: a level may count its solves).
    virtual std::string solver() const = 0;
    virtual std::string completeness() const = 0;
};

// The refusal of [rotation] at a level that cannot spin it (the coupled
// harmonics), naming the case file and the levels that can.
InputError cannot_spin(const Scene& scene, ModelChoice level);

// InputError naming the case file: a Campbell sweep at a level that solves
// with SLEPc runs in one process.
void require_one_process_sweep(const Scene& scene, ModelChoice level);

}  // namespace coremodal
