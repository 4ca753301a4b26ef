// [damping] on the lateral problem's modes at rest (docs/how-to/response.md): which
// ratio each mode takes — its own (a mode number of the scene at rest, as in
// modes.csv), its family's (its label's type), or the base (one ratio, or
// Rayleigh's alpha/(2 omega) + beta omega/2) — and the damping it gives
// LateralResponse (set_damping).
//
// The lateral problem's modes are the scene's bending modes (and any mixed
// ones), solved again on the lateral DOFs alone: a lateral mode is the scene
// mode (or degenerate pair) of the same eigenvalue (kClusterTolerance) whose
// shapes span it. A degenerate pair whirls as one, so a ratio given for
// either member damps both; two different ratios for one pair are refused.
#pragma once

#include "analyses/response/lateral_response.hpp"
#include "beam/beam_model.hpp"
#include "effects/damping.hpp"
#include "scene/response_spec.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// One lateral mode at rest and its damping.
struct ModeDamping {
    std::vector<int> rest_modes;  // its number(s) among the scene's modes at rest (1-based; a pair: two; none above them)
    ModeLabel label;
    double frequency_hz = 0;
    double zeta = 0;
    std::string from;  // "mode 1", "bending", "ratio", "rayleigh"
    double loss_factor = 0;  // eta_j = phi^T H phi / lambda_j of structural damping (0: none)
};

struct LateralDampingPlan {
    RayleighDamping rayleigh;                 // alpha = beta = 0 without a Rayleigh base
    std::vector<std::optional<double>> zeta;  // per lateral mode: its ratio, or empty for Rayleigh's
    std::vector<ModeDamping> modes;           // per lateral mode
    std::vector<std::string> assumptions;     // what the run echoes: the base, each family and mode given
};

// A mode of the scene at rest, numbered as in modes.csv (from 1).
struct NumberedRestMode {
    ModeLabel label;
    double frequency_hz = 0;
    bool lateral = false;  // one of the modes the lateral response is made of
};

// A mode at rest of the response's basis, lowest first, with the scene's
// modes at rest it is (its number(s); none above the modes the run computes).
struct BasisMode {
    double eigenvalue = 0;  // rad^2/s^2
    ModeLabel label;
    std::vector<int> rest_modes;
};

// The plan at any level: `lateral_words` says which modes make the lateral
// response ("bending only", "wave number n = 1 only") in the notes on a
// family or mode that damps nothing. Throws InputError (FILE:LINE:COL from
// the spec) for a mode number beyond `rest`, or two ratios for one
// degenerate pair.
LateralDampingPlan plan_modal_damping(const DampingSpec& spec, const std::vector<NumberedRestMode>& rest,
                                      const std::vector<BasisMode>& basis, const std::string& lateral_words);

// The beam level's: each lateral mode matched to the scene's modes at rest.
LateralDampingPlan plan_damping(const DampingSpec& spec, const BeamModelResult& rest, const LateralResponse& lateral);

// One line for people: "ratio 0.01 (...)", "Rayleigh ..."; with the families and modes given.
std::string damping_summary(const DampingSpec& spec);

// The loss factors of [damping] as the effect (effects/damping.hpp).
inline StructuralDamping structural_damping_of(const DampingSpec& spec) {
    return {spec.loss_factor, spec.part_loss_factors};
}
// What a run with structural damping assumes, echoed; `where` says what a
// part's stiffness is at the level ("the core's and rest paper's element
// stiffness", "each part's cells"). Empty without loss factors.
std::vector<std::string> structural_damping_assumptions(const DampingSpec& spec, const std::string& where);

// The loss factors of [damping] on a modal response whose static part keeps
// them (harmonic and solid levels): H from the level's parts, built only when
// a loss factor is given, and what that assumes, echoed.
template <class Response, class Hysteretic>
void add_structural_damping(Response& response, const DampingSpec& spec, Hysteretic&& hysteretic,
                            const std::string& where, std::vector<std::string>& assumptions) {
    const StructuralDamping structural = structural_damping_of(spec);
    if (!structural.given()) return;
    response.set_hysteretic(hysteretic(structural));
    for (std::string& a : structural_damping_assumptions(spec, where)) assumptions.push_back(std::move(a));
    assumptions.push_back(
        "structural damping: the static part of the modes above the cutoff with their loss, "
        "(K + i H)^-1 p less the kept modes' (Lambda + i Phi^T H Phi)^-1 part");
}

}  // namespace coremodal
