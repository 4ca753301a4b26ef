#include "analyses/select/rest_roll_limit.hpp"

#include "analyses/limits/limits.hpp"
#include "analyses/limits/limits_band.hpp"
#include "beam/beam_model.hpp"
#include "beam/formulas.hpp"
#include "beam/speeds.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "scene/materials_library.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace coremodal {
namespace {

// Below a micrometre of paper the rest roll is the bare core (as limits'
// scene_at_diameter).
constexpr double kBarePaper = 1e-6;  // m
// Modes of the candidate's beam: the first bending pair is among the lowest
// eight of a clamped roll (bending pairs, torsion, axial).
constexpr int kCandidateModes = 8;
// Steps of the calibration: f1 goes as sqrt(E_z) up to the Timoshenko shear,
// which does not scale; secant steps meet kCalibrationTolerance in three to five.
constexpr int kCalibrationSteps = 12;

OrthotropicMaterial library_material(std::string_view name, double e_z, double density) {
    OrthotropicMaterial m = to_material(*find_library_material(name));
    m.E_z = e_z;
    m.density = density;
    m.source = "[selection] (E_z, density) and the library's " + std::string(name) + " (the rest)";
    return m;
}

double rest_roll_dp(const CoreGrade& core, const Stand& stand) {
    return std::max(stand.rest_roll_diameter, core.outer_diameter);
}

RestRollSection section(const CoreGrade& c, const Stand& stand, const SelectionScene& s) {
    return {c.inner_diameter, c.outer_diameter,     rest_roll_dp(c, stand), c.flexural_modulus,
            c.density,        s.rest_paper_modulus, s.rest_paper_density};
}

// The candidate before calibration: core and rest roll, clamped over the
// chucks' supporting length.
Scene uncalibrated(const CoreGrade& core, const Stand& stand, const SelectionScene& selection, double width) {
    Scene s;
    s.name = selection.name + ": core " + core.name + " in stand " + stand.name;
    s.source_file = selection.source;
    s.model = ModelChoice::beam;
    s.core.inner_diameter = core.inner_diameter;
    s.core.outer_diameter = core.outer_diameter;
    s.core.length = width;
    s.core.material = library_material("paperboard_core", core.flexural_modulus, core.density);
    if (stand.rest_roll_diameter > core.outer_diameter + kBarePaper)
        s.rest_paper =
            RestPaperSpec{stand.rest_roll_diameter,
                          library_material("rest_paper", selection.rest_paper_modulus, selection.rest_paper_density)};
    s.supports.kind = SupportKind::clamped;
    s.supports.clamps = {{"left", 0.0, stand.chuck_length}, {"right", width - stand.chuck_length, width}};
    s.analysis.n_modes = kCandidateModes;
    return s;
}

double first_bending_hz(const Scene& scene) {
    for (const BeamMode& m : solve_beam_model(scene).modes)
        if (m.label.type == "bending") return m.frequency_hz;
    throw SolveError(scene.name + ": no bending mode among the lowest " + std::to_string(kCandidateModes) +
                     " modes of the calibrated beam");
}

void scale_axial_moduli(Scene& s, double factor) {
    s.core.material.E_z *= factor;
    if (s.rest_paper) s.rest_paper->material.E_z *= factor;
}

// The narrowest reel the stand holds: the clamps may not overlap and I-7 needs
// a free span.
double narrowest_width(const Stand& stand) { return 2 * std::max(stand.li, stand.chuck_length) + kWidthTolerance; }

// The search variable: the log of I-7's free span, in which every f1-driven
// criterion is nearly a straight line of slope -2 (f1 ~ 1/L^2).
double log_span(double width, const Stand& stand) { return std::log(width - 2 * stand.li); }
double width_of(double log_span_value, const Stand& stand) { return 2 * stand.li + std::exp(log_span_value); }

struct Probe {
    double width = 0;
    double log_ratio = 0;  // log(safe speed / web speed): >= 0 passes
    RestRollVerdict verdict;
};

}  // namespace

CandidateScene candidate_scene(const CoreGrade& core, const Stand& stand, const SelectionScene& selection,
                               double width) {
    CandidateScene c;
    c.scene = c.as_given = uncalibrated(core, stand, selection, width);
    c.target_f1_hz = ilomaki_first_bending_hz(section(core, stand, selection), free_span(width, stand.li),
                                              stand.chuck_factor);  // I-7 with k
    // Secant steps in (log factor, log f1): f1 goes as the factor^p, p = 1/2
    // without shear and less with it.
    double power = 0.5, last_log_factor = 0, last_log_f1 = 0;
    for (int step = 0; step < kCalibrationSteps; ++step) {
        const double f1 = first_bending_hz(c.scene);
        if (std::abs(f1 / c.target_f1_hz - 1) < kCalibrationTolerance) return c;
        const double log_factor = std::log(c.stiffness_factor), log_f1 = std::log(f1);
        if (step > 0 && log_factor != last_log_factor)
            power = std::clamp((log_f1 - last_log_f1) / (log_factor - last_log_factor), 0.05, 0.5);
        last_log_factor = log_factor, last_log_f1 = log_f1;
        const double scale = std::exp((std::log(c.target_f1_hz) - log_f1) / power);
        scale_axial_moduli(c.scene, scale);
        c.stiffness_factor *= scale;
    }
    throw SolveError(c.scene.name + " at width " + significant(width, 6) + " m: the beam's f1 (" +
                     significant(std::exp(last_log_f1), 6) + " Hz) did not meet I-7's " +
                     significant(c.target_f1_hz, 6) + " Hz with k = " + significant(stand.chuck_factor, 3) +
                     " after " + std::to_string(kCalibrationSteps) + " calibration steps (E_z factor " +
                     significant(c.stiffness_factor, 4) + ")");
}

RestRollVerdict rest_roll_verdict(const CoreGrade& core, const Stand& stand, const SelectionScene& selection,
                                  double width, double web_speed) {
    const CandidateScene c = candidate_scene(core, stand, selection, width);
    LimitsRequest request;
    const double dp = rest_roll_dp(core, stand);
    request.spec.largest_diameter_m = request.spec.smallest_diameter_m = dp;  // one diameter: the stand's rest roll
    request.spec.band = false;
    request.spec.limit_m = stand.amplitude_limit;
    const LimitsResult r = verdict(c.scene, std::nullopt, request);
    RestRollVerdict v;
    v.stiffness_factor = c.stiffness_factor;
    const LimitsPoint& p = r.points.front();
    v.f1_hz = p.f1_hz;
    // I-5 at the stand's own factor in place of the verdict's 0.7.
    std::vector<CriterionSpeed> criteria = p.criteria;
    CriterionSpeed& i5 = criteria[static_cast<int>(Criterion::i5_low)];
    i5.web_speed_m_s = safe_web_speed(p.f1_hz, dp, stand.safe_factor);
    // König's K-1/K-2 from the section as given: his experience factor already
    // stands for the chucks, so the calibrated E_z would count them twice.
    CriterionSpeed& koenig = criteria[static_cast<int>(Criterion::koenig)];
    if (const auto k = roll_speeds(c.as_given, p.f1_hz, "").koenig; k && koenig.given)
        koenig.web_speed_m_s = k->v_krit_large_core_m_s.value_or(k->speed.v_krit_m_s);
    const int lowest = lowest_limiting(criteria);
    if (lowest < 0) throw SolveError(c.scene.name + ": no criterion gives a web speed");
    const auto name = [&](int i) {
        return i == static_cast<int>(Criterion::i5_low) ? "I-5 x" + significant(stand.safe_factor, 3)
                                                        : std::string(criterion_name(static_cast<Criterion>(i)));
    };
    v.safe_speed_m_s = criteria[lowest].web_speed_m_s;
    v.governing = name(lowest);
    criteria[lowest].limits = false;  // the runner-up: how close the next criterion is
    if (const int next = lowest_limiting(criteria); next >= 0) {
        v.next = name(next);
        v.next_speed_m_s = criteria[next].web_speed_m_s;
    }
    v.passes = v.safe_speed_m_s >= web_speed;
    return v;
}

double i7_max_width(const CoreGrade& core, const Stand& stand, const SelectionScene& selection, double web_speed) {
    // v = safe pi Dp f1 and f1 = k C / L^2 (I-7) give L = sqrt(k C safe pi Dp /
    // v).
    const RestRollSection s = section(core, stand, selection);
    const double f1_at_unit_span = ilomaki_first_bending_hz(s, 1.0, stand.chuck_factor);
    const double span = std::sqrt(f1_at_unit_span * stand.safe_factor * std::numbers::pi * s.Dp / web_speed);
    return std::min(span + 2 * stand.li, kMaxSelectionWidth);
}

double max_width_for_speed(const CoreGrade& core, const Stand& stand, const SelectionScene& selection, double web_speed,
                           RestRollVerdict* at_limit) {
    const double narrowest = narrowest_width(stand);
    auto probe = [&](double w) {
        Probe p{w, 0, rest_roll_verdict(core, stand, selection, w, web_speed)};
        p.log_ratio = std::log(p.verdict.safe_speed_m_s / web_speed);
        return p;
    };
    std::optional<Probe> pass,
        fail;  // the widest passing and the narrowest failing width so far
    auto record = [&](const Probe& p) {
        if (p.verdict.passes && (!pass || p.width > pass->width)) pass = p;
        if (!p.verdict.passes && (!fail || p.width < fail->width)) fail = p;
    };
    double next = std::clamp(i7_max_width(core, stand, selection, web_speed), narrowest, kMaxSelectionWidth);
    for (int step = 0; step < 60; ++step) {
        const Probe p = probe(next);
        record(p);
        if (p.verdict.passes && p.width >= kMaxSelectionWidth) break;
        if (!p.verdict.passes && p.width <= narrowest) break;
        if (pass && fail && fail->width - pass->width <= kWidthTolerance) break;
        if (pass && fail) {
            // Inside the bracket: the secant in (log span, log ratio); every third
            // step halves it.
            const double xa = log_span(pass->width, stand), xb = log_span(fail->width, stand);
            double x = xa - pass->log_ratio * (xb - xa) / (fail->log_ratio - pass->log_ratio);
            if (step % 3 == 2 || !std::isfinite(x)) x = 0.5 * (xa + xb);
            next = std::clamp(width_of(x, stand), pass->width + 0.45 * kWidthTolerance,
                              fail->width - 0.45 * kWidthTolerance);
            // Right beside the last probe, across the root: a close estimate closes
            // the bracket.
            if (std::abs(next - p.width) < kWidthTolerance)
                next = p.verdict.passes
                           ? std::min(p.width + 0.9 * kWidthTolerance, fail->width - 0.45 * kWidthTolerance)
                           : std::max(p.width - 0.9 * kWidthTolerance, pass->width + 0.45 * kWidthTolerance);
        } else {
            // One side only: a Newton step with the slope -2 of f1 ~ 1/L^2 from the
            // last probe, and at least 0.9 tolerance beyond it: a probe on the root
            // (I-5 governing at the I-7 width) is bracketed by the next one.
            const double x = log_span(p.width, stand) + p.log_ratio / 2;
            const double w = width_of(x, stand);
            next = p.verdict.passes ? std::max(w, p.width + 0.9 * kWidthTolerance)
                                    : std::min(w, p.width - 0.9 * kWidthTolerance);
            next = std::clamp(next, narrowest, kMaxSelectionWidth);
        }
    }
    if (!pass) {
        if (at_limit) *at_limit = fail->verdict;
        return 0;
    }
    if (at_limit) *at_limit = pass->verdict;
    return pass->width >= kMaxSelectionWidth ? kMaxSelectionWidth : pass->width;
}

std::vector<std::string> rest_roll_assumptions() {
    return {"width limit: the `coremodal limits` verdict at the beam level (docs/how-to/limits.md) at the stand's "
            "rest_roll_diameter, without the band: I-5 at the stand's safe factor, Koenig K-1/K-2, the order-1 and "
            "order-2 critical speeds, the mid-span amplitude limit; the lowest governs",
            "the roll held rigidly over the chuck length at both ends, the axial moduli E_z of core and rest paper "
            "scaled by one factor so that the beam's first bending frequency at rest is I-7's with the stand's chuck "
            "factor k over width - 2 li (the calibration; the factor is listed per core); Koenig's formula on the "
            "section as given (his experience factor stands for the chucks)",
            "the verdict's excitation: damping ratio 0.01, a half-sine bow of 0.5 mm per metre of core "
            "(Ilomaki's straightness tolerance), gravity",
            "the core's other moduli from the library's paperboard_core, the rest paper's from rest_paper "
            "(docs/reference/material-sources.md)"};
}

}  // namespace coremodal
