// What a forced response gives (analyses/response/response.hpp has the
// steps): the amplitudes at the probes against speed, the peaks, the safe
// speed and the checks; with how the level is asked to check and what it
// solves at rest. Here, below analyses/, because every level's response
// model (models/response/response_model.hpp) speaks them.
#pragma once

#include "models/response/response_damping.hpp"
#include "beam/beam_model.hpp"
#include "beam/speeds.hpp"
#include "modes/mode_set.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The modes kept: every mode up to this multiple of the highest load
// frequency (order x top speed). Three puts the nearest left-out mode's
// dynamic amplification within 1/(3^2 - 1) = 12.5 % of its static part,
// which the static correction carries exactly; the reported truncation
// effect is measured against the complete basis at every run.
constexpr double kTruncationFactor = 3.0;
// Speeds (besides the peaks) at which the truncated sum, the complete basis
// and the direct solve are compared.
constexpr int kCheckSpeeds = 8;

struct ProbeAmplitude {
    double total_m = 0;              // sum over the orders of the orbits' semi-major axes
    std::vector<double> per_order_m;  // semi-major axis of each order's orbit
};

struct ResponsePoint {
    double speed_hz = 0;  // f_rot
    double web_speed_m_s = 0;
    std::vector<ProbeAmplitude> probes;
};

struct ResponsePeak {
    int order = 1;
    double speed_hz = 0, web_speed_m_s = 0;
    double amplitude_m = 0;  // at the first probe, total
    double excitation_hz = 0;  // order x f_rot
    ModeLabel mode;            // the mode at rest that carries most of the probe's motion
    double mode_frequency_hz = 0;  // its frequency at rest
};

// Where order x f_rot meets a whirl of the harmonic level's n = 1 model in
// the kept modes (ModalResponse::synchronous_crossings): the critical speeds
// of the model the response is computed in, without a Campbell sweep.
struct ResponseCrossing {
    int order = 1;
    bool forward = true;  // false: backward whirl
    double speed_hz = 0, web_speed_m_s = 0;
    ModeLabel mode;  // the kept mode with the largest share of the crossing's shape
};

struct AmplitudeSafeSpeed {
    bool reached = false;  // the amplitude reaches the limit within the range
    bool below_range = false;  // already at the first speed
    double speed_hz = 0, web_speed_m_s = 0;
    double implied_factor = 0;  // f_rot / f1 there: I-5's "safe" that this amplitude limit implies
};

struct ResponseChecks {
    int n_modes_all = 0, n_modes_used = 0;
    double cutoff_hz = 0;
    int speeds_checked = 0;
    int direct_speeds_checked = 0;  // of them, against the direct solve
    double truncation_max_relative = 0;  // |a_truncated - a_complete| / a_complete at the first probe
    double direct_max_relative = 0;      // ||x_complete - x_direct|| / ||x_direct||
    // false where the level has only the kept modes (harmonic): both
    // differences are then the truncated sum's against the direct solve.
    bool complete_basis = true;
};

struct ResponseResult {
    ModelChoice level = ModelChoice::beam;  // the model level that computed it: beam, harmonic or solid
    std::string solver;          // how, in a line (summary.json's model.solver)
    std::vector<ResponsePoint> points;
    std::vector<ResponseRange::Probe> probes;
    std::vector<int> orders;  // the orders with a load
    std::vector<std::vector<std::string>> order_sources;  // per order, the effects that load it
    std::vector<ResponsePeak> peaks;
    AmplitudeSafeSpeed safe;
    RollSpeeds speeds_at_rest;  // I-5 from the first bending frequency at rest
    double limit_m = 0;
    DampingSpec damping;                    // as the case gave it
    std::string damping_summary;            // one line for people (response_damping.hpp)
    std::vector<DampingValue> damping_values;  // the damping terms' inputs beyond the ratios, for the report
    std::vector<ModeDamping> mode_damping;  // the kept modes' damping, lowest first
    double sag_m = 0;  // static sag under gravity at the first probe (0 without gravity)
    double ovality_split = 0;
    double max_amplitude_m = 0;
    double max_amplitude_web_speed_m_s = 0;
    ResponseChecks checks;
    std::vector<ResponseCrossing> crossings;  // harmonic level, ascending speed; empty at the others
    double roll_outer_diameter = 0;
    bool from_web_speed = false;
    long n_dofs = 0;
    double solve_seconds = 0;
    std::vector<std::string> effects, notes, assumptions;
};

// Whether a run checks its superposition (step 5). `none` is for a caller
// that runs the same scene many times over and checks once (the verdict of
// `coremodal limits`: at the case's roll, not at every diameter and band
// sample); the beam level then keeps only the modes up to the cutoff
// (lateral_response.hpp), which is the same truncated sum without a dense
// eigensolve of every mode. ResponseChecks then holds no differences
// (speeds_checked = 0).
// `light` is for the same caller's one check (`coremodal limits`): at the
// beam level the modes up to the cutoff as `none` (no dense eigensolve of
// every mode) and the truncated sum against the direct sparse solve at every
// check speed (lateral_response.hpp: the kept modes' damping by Woodbury's
// identity), as the harmonic and solid levels check; there, without a
// complete basis, it is `full`.
enum class ResponseChecking { full, light, none };

// What step 1 solves at rest at the harmonic level. `every_wave_number`:
// the level's whole run (modes.csv's numbering, which [damping] mode numbers
// name). `lateral`: wave number n = 1 only, the response's own basis (f1 is
// its lowest bending mode, the same operators and eigensolver, so the same
// f1 to the solver's tolerance): for a caller that needs f1 and the
// response only (`coremodal limits`: half of its harmonic time). A
// [damping] naming mode numbers still gets the whole run. The beam and
// solid levels' runs at rest are the lateral problem's already.
enum class RestModes { every_wave_number, lateral };

// InputError, before any work, when the scene's level cannot take it: the
// harmonic and solid levels need a body of revolution.
void require_response_level(const Scene& scene);

// The semi-major axis of the orbit Re((ux, uy) e^{i omega t}) (m).
double orbit_semi_major(std::complex<double> ux, std::complex<double> uy);

}  // namespace coremodal
