#include "models/response/response_sweep.hpp"

#include "effects/rotation.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// Golden-section steps refining a peak between its grid neighbours: the
// bracket shrinks by 0.618 per step, 40 steps to 4e-9 of the grid spacing.
constexpr int kPeakSteps = 40;
// Bisection steps for the speed where the amplitude reaches the limit.
constexpr int kLimitSteps = 50;

std::vector<ResponsePoint> sweep(const ResponseModel& model, const std::vector<double>& speeds, double dp) {
    std::vector<ResponsePoint> out;
    for (double s : speeds) {
        const std::vector<Eigen::VectorXcd> x = model.solve(s, ResponseMethod::truncated);
        ResponsePoint p{s, web_speed(s, dp), {}};
        for (size_t i = 0; i < model.n_probes(); ++i) p.probes.push_back(model.at_probe(x, i));
        out.push_back(std::move(p));
    }
    return out;
}

// The maximum of the amplitude in [a, b] (golden section; the peak is the
// only maximum in the bracket of its two grid neighbours).
double refine_peak(const ResponseModel& model, double a, double b) {
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double c = b - g * (b - a), d = a + g * (b - a), fc = model.amplitude(c), fd = model.amplitude(d);
    for (int i = 0; i < kPeakSteps; ++i) {
        if (fc > fd) {
            b = d, d = c, fd = fc, c = b - g * (b - a), fc = model.amplitude(c);
        } else {
            a = c, c = d, fc = fd, d = a + g * (b - a), fd = model.amplitude(d);
        }
    }
    return 0.5 * (a + b);
}

// The order that peaks: the largest rise of its own amplitude over the
// larger of the two grid neighbours' (not the largest amplitude: a small
// order-2 resonance may sit on a larger order-1 background).
size_t peaking_order(const ProbeAmplitude& at, const ProbeAmplitude& left, const ProbeAmplitude& right) {
    size_t best = 0;
    double best_rise = -1;
    for (size_t k = 0; k < at.per_order_m.size(); ++k) {
        const double base = std::max(left.per_order_m[k], right.per_order_m[k]);
        const double rise = base > 0 ? at.per_order_m[k] / base : 0;
        if (rise > best_rise) best_rise = rise, best = k;
    }
    return best;
}

std::vector<ResponsePeak> find_peaks(const ResponseModel& model, const std::vector<ResponsePoint>& points, double dp) {
    std::vector<ResponsePeak> out;
    for (size_t i = 1; i + 1 < points.size(); ++i) {
        const double a = points[i].probes[0].total_m;
        if (!(a > points[i - 1].probes[0].total_m && a >= points[i + 1].probes[0].total_m)) continue;
        ResponsePeak peak;
        peak.speed_hz = refine_peak(model, points[i - 1].speed_hz, points[i + 1].speed_hz);
        peak.web_speed_m_s = web_speed(peak.speed_hz, dp);
        const ProbeAmplitude at = model.at_probe(model.solve(peak.speed_hz, ResponseMethod::truncated), 0);
        peak.amplitude_m = at.total_m;
        const size_t k = peaking_order(at, points[i - 1].probes[0], points[i + 1].probes[0]);
        peak.order = model.orders()[k];
        peak.excitation_hz = peak.order * peak.speed_hz;
        const AnsweringMode mode = model.answering_mode(k, peak.speed_hz);
        peak.mode = mode.label;
        peak.mode_frequency_hz = mode.frequency_hz;
        out.push_back(peak);
    }
    return out;
}

// The first speed where the amplitude at the first probe reaches the limit:
// on the grid, or earlier on a refined peak between grid speeds.
AmplitudeSafeSpeed safe_speed(const ResponseModel& model, const std::vector<ResponsePoint>& points,
                              const std::vector<ResponsePeak>& peaks, double limit, double f1, double dp) {
    AmplitudeSafeSpeed out;
    if (points.front().probes[0].total_m >= limit) {
        out.reached = out.below_range = true;
        out.speed_hz = points.front().speed_hz;
    } else {
        double hi = -1;
        for (const ResponsePoint& p : points)
            if (p.probes[0].total_m >= limit) {
                hi = p.speed_hz;
                break;
            }
        for (const ResponsePeak& peak : peaks)
            if (peak.amplitude_m >= limit && (hi < 0 || peak.speed_hz < hi)) hi = peak.speed_hz;
        if (hi < 0) return out;
        double lo = points.front().speed_hz;
        for (const ResponsePoint& p : points)
            if (p.speed_hz < hi && p.probes[0].total_m < limit) lo = p.speed_hz;
        for (int i = 0; i < kLimitSteps; ++i) {
            const double mid = 0.5 * (lo + hi);
            (model.amplitude(mid) >= limit ? hi : lo) = mid;
        }
        out.reached = true;
        out.speed_hz = hi;
    }
    out.web_speed_m_s = web_speed(out.speed_hz, dp);
    out.implied_factor = f1 > 0 ? out.speed_hz / f1 : 0;
    return out;
}

double relative(double a, double b) { return b == 0 ? std::abs(a) : std::abs(a - b) / std::abs(b); }

// At kCheckSpeeds grid speeds and at every peak: the truncated sum against
// the complete basis (the truncation's effect) and the complete basis
// against the direct solve (round-off); without a complete basis, the
// truncated sum against the direct solve, which then measures both.
void check(const ResponseModel& model, const std::vector<ResponsePoint>& points,
           const std::vector<ResponsePeak>& peaks, bool every_direct, ResponseChecks& out) {
    std::vector<double> speeds;
    const size_t step = std::max<size_t>(1, points.size() / kCheckSpeeds);
    for (size_t i = 0; i < points.size(); i += step) speeds.push_back(points[i].speed_hz);
    for (const ResponsePeak& p : peaks) speeds.push_back(p.speed_hz);
    out.complete_basis = model.has_complete_basis();
    for (size_t i = 0; i < speeds.size(); ++i) {
        const double s = speeds[i];
        const bool direct = every_direct || !out.complete_basis || i + 1 == speeds.size();
        const std::vector<Eigen::VectorXcd> t = model.solve(s, ResponseMethod::truncated);
        const std::vector<Eigen::VectorXcd> c =
            out.complete_basis ? model.solve(s, ResponseMethod::complete) : model.solve(s, ResponseMethod::direct);
        out.truncation_max_relative =
            std::max(out.truncation_max_relative, relative(model.at_probe(t, 0).total_m, model.at_probe(c, 0).total_m));
        if (!direct) continue;
        const std::vector<Eigen::VectorXcd> d = out.complete_basis ? model.solve(s, ResponseMethod::direct) : c;
        const std::vector<Eigen::VectorXcd>& compared = out.complete_basis ? c : t;
        for (size_t k = 0; k < c.size(); ++k)
            out.direct_max_relative = std::max(out.direct_max_relative, (compared[k] - d[k]).norm() / d[k].norm());
        ++out.direct_speeds_checked;
    }
    out.speeds_checked = static_cast<int>(speeds.size());
}

// The largest amplitude at the first probe, on the grid or on a refined peak.
void set_largest_amplitude(ResponseResult& out) {
    for (const ResponsePoint& p : out.points)
        if (p.probes[0].total_m > out.max_amplitude_m) out.max_amplitude_m = p.probes[0].total_m, out.max_amplitude_web_speed_m_s = p.web_speed_m_s;
    for (const ResponsePeak& p : out.peaks)
        if (p.amplitude_m > out.max_amplitude_m) out.max_amplitude_m = p.amplitude_m, out.max_amplitude_web_speed_m_s = p.web_speed_m_s;
}

}  // namespace

void sweep_response(const ResponseModel& model, const ResponseRange& range, double f1_hz, double dp,
                    ResponseResult& out, ResponseChecking checking) {
    out.points = sweep(model, range.speeds_hz, dp);
    out.peaks = find_peaks(model, out.points, dp);
    out.safe = safe_speed(model, out.points, out.peaks, range.limit_m, f1_hz, dp);
    set_largest_amplitude(out);
    if (checking != ResponseChecking::none)
        check(model, out.points, out.peaks, checking == ResponseChecking::full, out.checks);
}

}  // namespace coremodal
