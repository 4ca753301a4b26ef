#include "models/response/response_damping.hpp"

#include "beam/rotating_modes.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "eigensolve/tolerances.hpp"
#include "modes/tracking.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// The share of a lateral mode (M-normalised) that the scene's modes of the
// same eigenvalue must span for it to be theirs. Both are the same
// eigenproblem solved twice, so the share is 1 to round-off (~1e-12); a mode
// that merely shares the eigenvalue by accident spans ~0 of it.
constexpr double kSpannedShare = 0.99;

bool is_lateral(const ModeLabel& label) { return label.type == "bending" || label.type == "mixed"; }

// The scene's modes at rest (1-based) that are lateral mode j: those of its
// eigenvalue, when their shapes span it; none above the modes the run computes.
std::vector<int> rest_modes_of(const BeamModelResult& rest, const LateralResponse& lateral, int j) {
    const double lambda = lateral.eigenvalue(j);
    const double tolerance = kClusterTolerance * std::max(std::abs(lambda), rest.lambda_scale);
    const Eigen::VectorXd mass_shape = lateral.mode_mass_shape(j);  // M phi_j per network DOF
    std::vector<int> out;
    double spanned = 0;
    for (size_t k = 0; k < rest.modes.size(); ++k) {
        const BeamMode& m = rest.modes[k];
        if (!is_lateral(m.label) || std::abs(m.eigenvalue - lambda) > tolerance) continue;
        const double projection = m.shape.dot(mass_shape);  // both M-normalised
        spanned += projection * projection;
        out.push_back(static_cast<int>(k) + 1);
    }
    return spanned >= kSpannedShare ? out : std::vector<int>{};
}

std::string mode_words(const std::vector<int>& modes) {
    std::string out = (modes.size() > 1 ? "modes " : "mode ") + std::to_string(modes.front());
    for (size_t i = 1; i < modes.size(); ++i) out += (i + 1 == modes.size() ? " and " : ", ") + std::to_string(modes[i]);
    return out;
}

// A single mode's own ratio, shared by its degenerate partners.
std::optional<double> own_ratio(const DampingSpec& spec, const std::vector<int>& rest_modes, const ModeDamping& m,
                                std::string& from) {
    std::optional<double> out;
    for (int k : rest_modes)
        for (const DampingSpec::ModeRatio& given : spec.modes) {
            if (given.mode != k) continue;
            if (out && *out != given.ratio)
                throw InputError(given.where + " mode = " + std::to_string(k) + ": " + mode_words(rest_modes) +
                                 " are one degenerate pair (" + label_text(m.label) + ", " +
                                 significant(m.frequency_hz, 5) + " Hz) that whirls as one; expected one ratio for "
                                 "both, or give only one of them");
            out = given.ratio;
            from = "mode " + std::to_string(k);
        }
    return out;
}

void check_mode_numbers(const DampingSpec& spec, const std::vector<NumberedRestMode>& rest,
                        const std::string& lateral_words, std::vector<std::string>& notes) {
    const int n = static_cast<int>(rest.size());
    for (const DampingSpec::ModeRatio& given : spec.modes) {
        if (given.mode > n)
            throw InputError(given.where + " mode = " + std::to_string(given.mode) + " is not among the " +
                             std::to_string(n) + " modes at rest the run computes; expected a mode from 1 to " +
                             std::to_string(n) + " (as in modes.csv), or more [analysis] modes");
        const NumberedRestMode& m = rest[static_cast<size_t>(given.mode - 1)];
        if (!m.lateral)
            notes.push_back("[damping] mode " + std::to_string(given.mode) + " (" + label_text(m.label) + ", " +
                            significant(m.frequency_hz, 5) + " Hz) is not in the lateral response (" + lateral_words +
                            "): its ratio " + significant(given.ratio, 4) + " damps nothing here");
    }
}

std::vector<std::string> plan_assumptions(const DampingSpec& spec, const LateralDampingPlan& plan,
                                          const std::string& lateral_words) {
    std::vector<std::string> out{"damping of every mode not named otherwise: " + spec.source +
                                 (spec.rayleigh ? "; mode j: zeta_j = alpha / (2 omega_j) + beta omega_j / 2" : "")};
    for (const DampingSpec::FamilyRatio& f : spec.families) {
        const auto n = std::count_if(plan.modes.begin(), plan.modes.end(), [&](const ModeDamping& m) { return m.from == f.family; });
        out.push_back("[damping] " + f.family + " = " + significant(f.ratio, 4) + ": " +
                      (n > 0 ? std::to_string(n) + " " + f.family + " modes of the lateral problem"
                             : "no " + f.family + " mode in the lateral response (" + lateral_words +
                                   "): it damps nothing here"));
    }
    for (const DampingSpec::ModeRatio& g : spec.modes)
        for (const ModeDamping& m : plan.modes)
            if (m.from == "mode " + std::to_string(g.mode)) {
                out.push_back("[damping] mode " + std::to_string(g.mode) + " (" + label_text(m.label) + ", " +
                              significant(m.frequency_hz, 5) + " Hz" +
                              (m.rest_modes.size() > 1 ? "; one degenerate pair, " + mode_words(m.rest_modes) : "") +
                              "): zeta = " + significant(g.ratio, 4));
                break;
            }
    return out;
}

}  // namespace

LateralDampingPlan plan_modal_damping(const DampingSpec& spec, const std::vector<NumberedRestMode>& rest,
                                      const std::vector<BasisMode>& basis, const std::string& lateral_words) {
    LateralDampingPlan plan;
    if (spec.rayleigh) plan.rayleigh = {spec.rayleigh->alpha, spec.rayleigh->beta};
    std::vector<std::string> notes;
    check_mode_numbers(spec, rest, lateral_words, notes);
    for (const BasisMode& b : basis) {
        ModeDamping m;
        const double lambda = b.eigenvalue;
        m.frequency_hz = std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI);
        m.label = b.label;
        m.rest_modes = b.rest_modes;
        std::optional<double> zeta = own_ratio(spec, m.rest_modes, m, m.from);
        if (!zeta)
            for (const DampingSpec::FamilyRatio& f : spec.families)
                if (f.family == m.label.type) zeta = f.ratio, m.from = f.family;
        if (!zeta && !spec.rayleigh) zeta = spec.ratio, m.from = "ratio";
        if (!zeta) m.from = "rayleigh";
        m.zeta = zeta ? *zeta : lambda > 0 ? plan.rayleigh.zeta(std::sqrt(lambda)) : 0.0;
        plan.zeta.push_back(zeta);
        plan.modes.push_back(std::move(m));
    }
    plan.assumptions = plan_assumptions(spec, plan, lateral_words);
    for (const std::string& n : notes) plan.assumptions.push_back(n);
    return plan;
}

LateralDampingPlan plan_damping(const DampingSpec& spec, const BeamModelResult& rest, const LateralResponse& lateral) {
    std::vector<NumberedRestMode> numbered;
    for (const BeamMode& m : rest.modes) numbered.push_back({m.label, m.frequency_hz, is_lateral(m.label)});
    std::vector<BasisMode> basis;
    for (int j = 0; j < lateral.n_modes(); ++j) {
        const double lambda = lateral.eigenvalue(j);
        basis.push_back({lambda,
                         label_beam_mode(rest.network, lateral.mode_shape(j), lateral.mode_mass_shape(j), lambda,
                                         rest.lambda_scale),
                         rest_modes_of(rest, lateral, j)});
    }
    return plan_modal_damping(spec, numbered, basis, "bending only");
}

std::string damping_summary(const DampingSpec& spec) {
    // The source of a Rayleigh base names alpha and beta already.
    std::string out = spec.rayleigh ? spec.source : "zeta = " + significant(spec.ratio, 4) + " (" + spec.source + ")";
    for (const DampingSpec::FamilyRatio& f : spec.families) out += "; " + f.family + " " + significant(f.ratio, 4);
    for (const DampingSpec::ModeRatio& m : spec.modes)
        out += "; mode " + std::to_string(m.mode) + " " + significant(m.ratio, 4);
    if (const std::string words = loss_factor_words(spec); !words.empty()) out += "; structural damping: " + words;
    return out;
}

std::vector<DampingValue> damping_input_values(const DampingSpec& spec) {
    if (loss_factor_words(spec).empty()) return {};
    std::vector<DampingValue> out{{"/loss_factor", "", spec.loss_factor}};
    for (const auto& [part, eta] : spec.part_loss_factors) out.push_back({"/loss_factors/" + part, "", eta});
    return out;
}

std::vector<std::string> damping_effect_names(const DampingSpec& d) {
    std::vector<std::string> out;
    if ((!d.rayleigh && d.ratio > 0) || !d.families.empty() || !d.modes.empty()) out.push_back(ModalDamping::kName);
    for (std::string& e : operator_damping_effects(d)) out.push_back(std::move(e));  // Rayleigh's, the loss factors'
    return out;
}

std::string damping_note(const DampingSpec& spec) {
    return "damping in the stationary frame (bearings, air, web), per mode at rest (ratios, Rayleigh's alpha M + beta K); "
           "no rotating (internal) damping, " +
           std::string(loss_factor_words(spec).empty() ? "no loss factors per part"
                                                       : "a loss factor per part (structural damping, K_p (1 + i eta_p))");
}

bool same_part_damping(const DampingSpec& a, const DampingSpec& b) {
    return a.loss_factor == b.loss_factor && a.part_loss_factors == b.part_loss_factors;
}

std::vector<std::string> part_damping_assumptions(const DampingSpec& spec, const std::string& where,
                                                  bool static_part_keeps_loss) {
    if (!structural_damping_of(spec).given()) return {};
    return {"structural (hysteretic) damping, " + loss_factor_words(spec) +
                ": the complex stiffness K_p (1 + i eta_p) of " + where +
                ", frequency independent (H = sum eta_p K_p in the direct solve, Phi^T H Phi in the modal equations: "
                "mode j's loss factor eta_j = phi_j^T H phi_j / lambda_j, at resonance as a viscous zeta_j = eta_j / 2); "
                "springs (spring layers, bearings) carry no loss factor; the values are the user's (no default)",
            static_part_keeps_loss
                ? "structural damping: the static part of the modes above the cutoff with their loss, "
                  "(K + i H)^-1 p less the kept modes' (Lambda + i Phi^T H Phi)^-1 part"
                : "structural damping: the static part of the modes above the cutoff is taken without "
                  "their loss (it changes it by 1/(1 + i eta): in magnitude by about eta^2 / 2)"};
}

}  // namespace coremodal
