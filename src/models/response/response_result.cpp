#include "models/response/response_levels.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "effects/damping.hpp"
#include "effects/excitation.hpp"
#include "effects/rotation.hpp"
#include "models/choose.hpp"
#include "models/response/level_response.hpp"

#include <cmath>
#include <complex>

namespace coremodal {
namespace {

using cd = std::complex<double>;

// The level's own first note, then what every level shares.
std::vector<std::string> response_notes(const ResponseSetup& setup, const ResponseLevel& level) {
    const ExcitationSpec& x = setup.excitation;
    std::vector<std::string> notes{
        level.note,
        damping_note(setup.damping),
        "amplitude: the orbit's semi-major axis of the axis' total displacement (the bow's runout included: what a laser "
        "sees, less the surface's own out-of-roundness), summed over the orders (the largest excursion when their "
        "phases align)"};
    if (x.gravity)
        notes.push_back("gravity: the static sag is reported, not counted as vibration");
    if (x.ovality_m > 0 && !x.gravity)
        notes.push_back("[excitation] ovality without gravity excites nothing at the " + to_string(level.level) + " level (gravity = false)");
    return notes;
}

// What the run assumed beyond the file, each with its source (summary.json, report.md).
std::vector<std::string> setup_assumptions(const ResponseSetup& setup) {
    const ExcitationSpec& x = setup.excitation;
    std::vector<std::string> out;
    if (setup.response.limit_m == kDefaultAmplitudeLimit)
        out.push_back("amplitude limit 5 mm at " + setup.response.probes.front().name +
                      ": the default, Ilomaki's +-5 mm at mid-span (Ilomäki; docs/reference/references.md)");
    if (x.bow_m > 0)
        out.push_back(x.bow_shape == BowShape::half_sine
                          ? "bow: a half sine b sin(pi z / Lc) over the core length with its slope as the section "
                            "rotation (the default bow_shape), stress-free in that shape; chucks and clamps straight"
                          : "bow: the first bending mode at rest, scaled to the bow at mid-core, stress-free in that shape");
    if ((x.unbalance_kg_m > 0 || x.eccentricity_m > 0) && x.bow_m > 0)
        out.push_back("unbalance and bow at the same angle (in phase): their order-1 amplitudes add");
    if (x.unbalance_kg_m > 0) out.push_back("unbalance: a point mass at mid-core");
    if (x.gravity)
        out.push_back("gravity: " + significant(kGravity, 6) + " m/s^2 (standard gravity), vertical" +
                      std::string(x.ovality_m > 0 ? "; with the ovality, a load turning at twice the speed" : ""));
    return out;
}

std::vector<std::string> effect_names(const Scene& scene, const ResponseSetup& setup) {
    const ExcitationSpec& x = setup.excitation;
    std::vector<std::string> out = scene.effects();
    out.push_back(Gyroscopic::kName);
    for (const std::string& e : damping_effect_names(setup.damping)) out.push_back(e);
    for (const std::string& e : excitation_effect_names(x)) out.push_back(e);
    return out;
}

}  // namespace

double orbit_semi_major(cd ux, cd uy) {
    // The orbit as a complex position qx + i qy = F e^{i w t} + B e^{-i w t}:
    // a forward circle F = (ux + i uy) / 2 and a backward one B = (conj ux +
    // i conj uy) / 2; the semi-major axis is |F| + |B| (the minor ||F| - |B||).
    // (Not the singular values by their quadratic formula, which cancels for
    // a circular orbit and loses half the digits.)
    const cd I(0, 1);
    return 0.5 * (std::abs(ux + I * uy) + std::abs(std::conj(ux) + I * std::conj(uy)));
}

ResponseResult response_result_for(const Scene& scene, const ResponseSetup& setup, const ResponseLevel& level) {
    ResponseResult out;
    out.level = level.level;
    const ResponseRange& range = setup.response;
    out.probes = range.probes, out.limit_m = range.limit_m, out.from_web_speed = range.from_web_speed;
    out.damping = setup.damping, out.damping_summary = damping_summary(setup.damping);
    out.damping_values = damping_input_values(setup.damping);
    out.roll_outer_diameter = roll_outer_diameter(scene);
    out.effects = effect_names(scene, setup);
    out.notes = response_notes(setup, level);
    out.assumptions = setup_assumptions(setup);
    return out;
}

std::string kept_modes_assumption(const ResponseChecks& checks, const std::string& modes_words) {
    return "modes kept: " + std::to_string(checks.n_modes_used) + " of " + std::to_string(checks.n_modes_all) + " " +
           modes_words + ", up to " + significant(checks.cutoff_hz, 4) + " Hz (" + significant(kTruncationFactor, 2) +
           " x the highest load frequency), with the static part of the others";
}

void require_response_level(const Scene& scene) {
    const LevelTraits& level = level_traits(chosen_level(scene));
    if (!level.spins)
        throw InputError(scene.source_file + ": [response] at the " + to_string(level.level) + " level: " +
                         level.why_not_spinning + " (docs/theory/coupled.md); expected a body of revolution at model = "
                         "\"harmonic\", \"solid\" or \"beam\"");
    if (level.axisymmetric_only) require_axisymmetric(scene);
    if (const auto why = why_not_axisymmetric(scene); why && level.response_needs_revolution)
        throw InputError(scene.source_file + ": [response] at the " + to_string(level.level) + " level: " + *why +
                         "; the gyroscopic term is the stationary frame's, right for a body of revolution only "
                         "(docs/theory/rotation-solid.md); expected full bands, no [mesh] file and expanded chucks");
}

std::vector<ResponseResult> LevelResponse::respond_all(const std::vector<ResponseSetup>& setups,
                                                   ResponseChecking checking, RestModes rest) {
    std::vector<ResponseResult> out;
    for (const ResponseSetup& s : setups) out.push_back(respond(s, checking, rest));
    return out;
}

}  // namespace coremodal
