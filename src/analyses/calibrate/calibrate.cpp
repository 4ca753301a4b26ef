#include "analyses/calibrate/calibrate.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// Four coefficients and at least one degree of freedom for the residuals.
constexpr int kMinFitPoints = kCalibrationGroups + 2;

Range range_of(const std::vector<double>& v) {
    return {*std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end())};
}

// "clamped" or "chucks"; "mixed" when the sweep varies the kind of support.
std::string supports_of(const std::vector<CalibrationRow>& rows) {
    std::string kind;
    for (const CalibrationRow& r : rows)
        if (r.used) kind = kind.empty() || kind == r.point->supports ? r.point->supports : "mixed";
    return kind;
}

void select_rows(const StudyResult& result, int holdout_every, std::vector<CalibrationRow>& rows) {
    int usable = 0;
    for (const StudyPoint& p : result.points) {
        CalibrationRow row;
        row.point = &p;
        if (!p.ok) {
            row.note = "failed";
        } else if (!p.f1_hz) {
            row.note = "no bending mode among the modes computed; raise [calibration] modes";
        } else if (!p.k) {
            row.note = "no chuck factor: the scene is not held in a stand";
        } else {
            row.used = true;
            row.groups = *p.chuck_groups;
            row.k_fe = *p.k;
            row.held_out = ++usable % holdout_every == 0;
        }
        rows.push_back(row);
    }
}

}  // namespace

CalibrationOutcome calibrate_chuck_factor(const CaseSweep& sweep, const StudyResult& result) {
    CalibrationOutcome out;
    select_rows(result, sweep.options().holdout_every, out.rows);
    std::vector<CalibrationSample> fit;
    int n_held = 0;
    for (const CalibrationRow& r : out.rows) {
        if (r.used && !r.held_out) fit.push_back({r.groups, r.k_fe});
        n_held += r.used && r.held_out;
    }
    if (static_cast<int>(fit.size()) < kMinFitPoints || n_held == 0)
        throw InputError(sweep.case_file() + ": [calibration] gave " + std::to_string(fit.size()) +
                         " points to fit and " + std::to_string(n_held) + " to hold out (holdout_every = " +
                         std::to_string(sweep.options().holdout_every) + "); expected at least " +
                         std::to_string(kMinFitPoints) + " to fit and 1 held out: more values or a smaller "
                         "holdout_every");
    Calibration& c = out.calibration;
    c.law = fit_chuck_factor(fit);
    c.case_name = sweep.case_name();
    c.case_file = sweep.case_file();
    c.stated_error = sweep.options().max_error;
    std::vector<double> g1, g2, g3, span, li, diameter;
    double sum_square = 0;
    for (CalibrationRow& r : out.rows) {
        if (!r.used) continue;
        const StudyPoint& p = *r.point;
        r.k_fit = c.law.k(r.groups);
        r.f1_calibrated_hz = r.k_fit * *p.f_i7_hz;
        r.error = std::abs(r.f1_calibrated_hz - *p.f1_hz) / *p.f1_hz;
        g1.push_back(r.groups.g1), g2.push_back(r.groups.g2), g3.push_back(r.groups.g3), span.push_back(*p.span_m), li.push_back(*p.li_m);
        diameter.push_back(p.diameter_m);
        if (r.held_out) {
            ++c.n_held_out;
            c.max_error_held_out = std::max(c.max_error_held_out, r.error);
        } else {
            ++c.n_fit;
            const double residual = r.k_fit - r.k_fe;
            sum_square += residual * residual;
            c.max_residual_k = std::max(c.max_residual_k, std::abs(residual));
            c.max_error_fit = std::max(c.max_error_fit, r.error);
        }
    }
    c.rms_residual_k = std::sqrt(sum_square / c.n_fit);
    c.g1 = range_of(g1), c.g2 = range_of(g2), c.g3 = range_of(g3), c.span_m = range_of(span), c.li_m = range_of(li);
    c.diameter_m = range_of(diameter);
    c.supports = supports_of(out.rows);
    c.passed = c.max_error_fit <= c.stated_error && c.max_error_held_out <= c.stated_error;
    return out;
}

}  // namespace coremodal
