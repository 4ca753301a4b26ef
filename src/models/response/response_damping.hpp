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

#include "models/response/lateral_response.hpp"
#include "beam/beam_model.hpp"
#include "effects/damping.hpp"
#include "scene/response_spec.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// A value a damping term adds to the result beyond the ratios, which the
// report writes as it is: its place in summary.json's damping table (a JSON
// pointer: "/loss_factor", "/loss_factors/core"; per kept mode "/loss_factor"),
// the heading of its column in the kept modes' table, the value.
struct DampingValue {
    std::string path, heading;
    double value = 0;
};

// One lateral mode at rest and its damping.
struct ModeDamping {
    std::vector<int> rest_modes;  // its number(s) among the scene's modes at rest (1-based; a pair: two; none above them)
    ModeLabel label;
    double frequency_hz = 0;
    double zeta = 0;
    std::string from;  // "mode 1", "bending", "ratio", "rayleigh"
    std::vector<DampingValue> values;  // the terms' own (structural damping: eta_j = phi^T H phi / lambda_j)
    // A value by its path ("/loss_factor"), 0 when the mode has none.
    double value_of(std::string_view path) const {
        for (const DampingValue& v : values)
            if (v.path == path) return v.value;
        return 0;
    }
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

// The damping of the n lowest (kept) modes of a response (LateralResponse,
// ModalResponse): the plan's, with each mode's loss factor
// eta_j = phi_j^T H phi_j / lambda_j from the response's projected H.
template <class Response>
std::vector<ModeDamping> kept_mode_damping(const LateralDampingPlan& plan, const Response& response, int n) {
    std::vector<ModeDamping> out(plan.modes.begin(), plan.modes.begin() + n);
    const Eigen::MatrixXd& H_hat = response.hysteretic_on_modes();
    if (H_hat.size() > 0)
        for (int j = 0; j < n; ++j)
            if (const double eta = StructuralDamping::modal_loss_factor(H_hat(j, j), response.eigenvalue(j)); eta > 0)
                out[static_cast<size_t>(j)].values.push_back({"/loss_factor", "loss factor eta_j", eta});
    return out;
}

// One line for people: "ratio 0.01 (...)", "Rayleigh ..."; with the families and modes given.
std::string damping_summary(const DampingSpec& spec);

// The loss factors of [damping] as the effect (effects/damping.hpp).
inline StructuralDamping structural_damping_of(const DampingSpec& spec) {
    return {spec.loss_factor, spec.part_loss_factors};
}
// The damping terms' inputs as the result carries them for the report
// (DampingValue): structural damping's loss factors.
std::vector<DampingValue> damping_input_values(const DampingSpec& spec);
// The damping effects [damping] names (effects/damping.hpp's kName), for the effects list.
std::vector<std::string> damping_effect_names(const DampingSpec& spec);
// The response's note on its damping: where it acts, what is not modelled,
// and whether the parts carry loss factors.
std::string damping_note(const DampingSpec& spec);
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
