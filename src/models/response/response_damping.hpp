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

#include <functional>
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
    const Eigen::MatrixXd& H_hat = response.imaginary_stiffness_on_modes();
    if (H_hat.size() > 0)
        for (int j = 0; j < n; ++j)
            if (const double eta = StructuralDamping::modal_loss_factor(H_hat(j, j), response.eigenvalue(j)); eta > 0)
                out[static_cast<size_t>(j)].values.push_back({"/loss_factor", "loss factor eta_j", eta});
    return out;
}

// One line for people: "ratio 0.01 (...)", "Rayleigh ..."; with the families and modes given.
std::string damping_summary(const DampingSpec& spec);

// The damping terms' inputs as the result carries them for the report
// (DampingValue): structural damping's loss factors.
std::vector<DampingValue> damping_input_values(const DampingSpec& spec);
// The damping effects [damping] names (effects/damping.hpp's kName), for the effects list.
std::vector<std::string> damping_effect_names(const DampingSpec& spec);
// The response's note on its damping: where it acts, what is not modelled,
// and whether the parts carry loss factors.
std::string damping_note(const DampingSpec& spec);
// A level's stiffness by part, for the damping terms that act on a part's
// material (effects/damping.hpp: a loss factor per part): K_p on the
// response's n rows for each of the level's parts, and what a part's
// stiffness is at the level ("each part's cells"), for the echo. The
// level's own operators; no damping in them.
struct PartStiffness {
    Eigen::Index n = 0;
    std::vector<std::string> parts;
    std::function<Eigen::SparseMatrix<double>(const std::string& part)> of;
    std::string where;
};

// Whether two setups ask the same damping of the parts (one model serves both).
bool same_part_damping(const DampingSpec& a, const DampingSpec& b);

// What a run with damping per part assumes, echoed; `static_part_keeps_loss`:
// whether the response's static part of the modes above the cutoff keeps
// their loss (ModalResponse) or not (LateralResponse). Empty without it.
std::vector<std::string> part_damping_assumptions(const DampingSpec& spec, const std::string& where,
                                                  bool static_part_keeps_loss);

// The damping terms of [damping] that act on the level's parts, on a modal
// response (LateralResponse, ModalResponse): built from the parts only when
// [damping] names one, with what that assumes, echoed.
template <class Response>
void add_part_damping(Response& response, const DampingSpec& spec, const PartStiffness& parts,
                      std::vector<std::string>& assumptions) {
    const StructuralDamping structural = structural_damping_of(spec);
    if (!structural.given()) return;
    response.set_imaginary_stiffness(
        hysteretic_operator(structural, parts.parts, Eigen::SparseMatrix<double>(parts.n, parts.n), parts.of));
    for (std::string& a : part_damping_assumptions(spec, parts.where, Response::kStaticPartKeepsLoss))
        assumptions.push_back(std::move(a));
}

}  // namespace coremodal
