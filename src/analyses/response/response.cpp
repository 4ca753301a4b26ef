#include "analyses/response/response.hpp"

#include "analyses/response/lateral_response.hpp"
#include "analyses/response/response_loads.hpp"
#include "beam/rotating_modes.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/stopwatch.hpp"
#include "effects/damping.hpp"
#include "effects/excitation.hpp"
#include "effects/rotation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace coremodal {
namespace {

using cd = std::complex<double>;

// Golden-section steps refining a peak between its grid neighbours: the
// bracket shrinks by 0.618 per step, 40 steps to 4e-9 of the grid spacing.
constexpr int kPeakSteps = 40;
// Bisection steps for the speed where the amplitude reaches the limit.
constexpr int kLimitSteps = 50;

enum class Method { truncated, complete, direct };

// The response of the network at one speed by one method, and its orbits.
class Evaluator {
public:
    Evaluator(const LateralResponse& lateral, const ResponseLoads& loads, std::vector<CorePoint> probes, int n_used)
        : lateral_(lateral), loads_(loads), probes_(std::move(probes)), n_used_(n_used) {}

    // Per order, x on the lateral problem's rows.
    std::vector<Eigen::VectorXcd> solve(double speed_hz, Method method) const {
        const double spin = 2 * M_PI * speed_hz;
        std::vector<Eigen::VectorXcd> out;
        for (const OrderLoad& load : loads_.orders) {
            const Eigen::VectorXcd f = lateral_.to_rows(load.at(spin));
            const double omega = load.order * spin;
            if (method == Method::direct) out.push_back(lateral_.direct(f, spin, omega));
            else if (method == Method::complete) out.push_back(lateral_.superpose(f, spin, omega, lateral_.n_modes()));
            else out.push_back(lateral_.superpose(f, spin, omega, n_used_, true));
        }
        return out;
    }

    ProbeAmplitude at_probe(const std::vector<Eigen::VectorXcd>& x, size_t probe) const {
        ProbeAmplitude a;
        for (const Eigen::VectorXcd& rows : x) {
            const Eigen::VectorXcd net = lateral_.to_network(rows);
            cd ux = 0, uy = 0;
            for (int k = 0; k < 3; ++k) {
                ux += probes_[probe].shape[k] * net(beam_dof::per_node * probes_[probe].nodes[k] + beam_dof::ux);
                uy += probes_[probe].shape[k] * net(beam_dof::per_node * probes_[probe].nodes[k] + beam_dof::uy);
            }
            a.per_order_m.push_back(orbit_semi_major(ux, uy));
            a.total_m += a.per_order_m.back();
        }
        return a;
    }

    double amplitude(double speed_hz) const { return at_probe(solve(speed_hz, Method::truncated), 0).total_m; }
    size_t n_probes() const { return probes_.size(); }
    const CorePoint& probe(size_t i) const { return probes_[i]; }

private:
    const LateralResponse& lateral_;
    const ResponseLoads& loads_;
    std::vector<CorePoint> probes_;
    int n_used_;
};

double first_bending_hz(const BeamModelResult& rest) {
    for (const BeamMode& m : rest.modes)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}

Eigen::VectorXd first_bending_shape(const BeamModelResult& rest) {
    for (const BeamMode& m : rest.modes)
        if (m.label.type == "bending") return m.shape;
    throw SolveError("the roll has no bending mode among the modes at rest; expected [analysis] modes to include one");
}

std::vector<ResponsePoint> sweep(const Evaluator& eval, const std::vector<double>& speeds, double dp) {
    std::vector<ResponsePoint> out;
    for (double s : speeds) {
        const std::vector<Eigen::VectorXcd> x = eval.solve(s, Method::truncated);
        ResponsePoint p{s, web_speed(s, dp), {}};
        for (size_t i = 0; i < eval.n_probes(); ++i) p.probes.push_back(eval.at_probe(x, i));
        out.push_back(std::move(p));
    }
    return out;
}

// The maximum of the amplitude in [a, b] (golden section; the peak is the
// only maximum in the bracket of its two grid neighbours).
double refine_peak(const Evaluator& eval, double a, double b) {
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double c = b - g * (b - a), d = a + g * (b - a), fc = eval.amplitude(c), fd = eval.amplitude(d);
    for (int i = 0; i < kPeakSteps; ++i) {
        if (fc > fd) {
            b = d, d = c, fd = fc, c = b - g * (b - a), fc = eval.amplitude(c);
        } else {
            a = c, c = d, fc = fd, d = a + g * (b - a), fd = eval.amplitude(d);
        }
    }
    return 0.5 * (a + b);
}

// The mode at rest with the largest share of the probe's motion in the order's response.
int answering_mode(const LateralResponse& lateral, const OrderLoad& load, const CorePoint& probe, double speed_hz, int n) {
    const double spin = 2 * M_PI * speed_hz;
    const Eigen::VectorXcd eta = lateral.modal_coordinates(lateral.to_rows(load.at(spin)), spin, load.order * spin, n);
    int best = 0;
    double best_share = -1;
    for (int j = 0; j < n; ++j) {
        const Eigen::VectorXd phi = lateral.mode_shape(j);
        double at_probe = 0;
        for (int k = 0; k < 3; ++k)
            at_probe += probe.shape[k] * std::hypot(phi(beam_dof::per_node * probe.nodes[k] + beam_dof::ux),
                                                    phi(beam_dof::per_node * probe.nodes[k] + beam_dof::uy));
        const double share = std::abs(eta(j)) * std::abs(at_probe);
        if (share > best_share) best_share = share, best = j;
    }
    return best;
}

struct PeakContext {
    const Evaluator& eval;
    const LateralResponse& lateral;
    const ResponseLoads& loads;
    const BeamModelResult& rest;
    int n_used;
    double dp;
};

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

std::vector<ResponsePeak> find_peaks(const PeakContext& c, const std::vector<ResponsePoint>& points) {
    std::vector<ResponsePeak> out;
    for (size_t i = 1; i + 1 < points.size(); ++i) {
        const double a = points[i].probes[0].total_m;
        if (!(a > points[i - 1].probes[0].total_m && a >= points[i + 1].probes[0].total_m)) continue;
        ResponsePeak peak;
        peak.speed_hz = refine_peak(c.eval, points[i - 1].speed_hz, points[i + 1].speed_hz);
        peak.web_speed_m_s = web_speed(peak.speed_hz, c.dp);
        const ProbeAmplitude at = c.eval.at_probe(c.eval.solve(peak.speed_hz, Method::truncated), 0);
        peak.amplitude_m = at.total_m;
        const size_t k = peaking_order(at, points[i - 1].probes[0], points[i + 1].probes[0]);
        peak.order = c.loads.orders[k].order;
        peak.excitation_hz = peak.order * peak.speed_hz;
        const int j = answering_mode(c.lateral, c.loads.orders[k], c.eval.probe(0), peak.speed_hz, c.n_used);
        peak.mode_frequency_hz = c.lateral.mode_frequency_hz(j);
        const double lambda = std::pow(2 * M_PI * peak.mode_frequency_hz, 2);
        peak.mode = label_beam_mode(c.rest.network, c.lateral.mode_shape(j), c.lateral.mode_mass_shape(j), lambda,
                                    c.rest.lambda_scale);
        out.push_back(peak);
    }
    return out;
}

// The first speed where the amplitude at the first probe reaches the limit:
// on the grid, or earlier on a refined peak between grid speeds.
AmplitudeSafeSpeed safe_speed(const Evaluator& eval, const std::vector<ResponsePoint>& points,
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
            (eval.amplitude(mid) >= limit ? hi : lo) = mid;
        }
        out.reached = true;
        out.speed_hz = hi;
    }
    out.web_speed_m_s = web_speed(out.speed_hz, dp);
    out.implied_factor = f1 > 0 ? out.speed_hz / f1 : 0;
    return out;
}

double relative(double a, double b) { return b == 0 ? std::abs(a) : std::abs(a - b) / std::abs(b); }

// The truncated sum against the complete basis, the complete basis against
// the direct solve, at kCheckSpeeds grid speeds and at every peak.
void check(const Evaluator& eval, const std::vector<ResponsePoint>& points, const std::vector<ResponsePeak>& peaks,
           ResponseChecks& out) {
    std::vector<double> speeds;
    const size_t step = std::max<size_t>(1, points.size() / kCheckSpeeds);
    for (size_t i = 0; i < points.size(); i += step) speeds.push_back(points[i].speed_hz);
    for (const ResponsePeak& p : peaks) speeds.push_back(p.speed_hz);
    for (double s : speeds) {
        const std::vector<Eigen::VectorXcd> t = eval.solve(s, Method::truncated), c = eval.solve(s, Method::complete),
                                            d = eval.solve(s, Method::direct);
        out.truncation_max_relative =
            std::max(out.truncation_max_relative, relative(eval.at_probe(t, 0).total_m, eval.at_probe(c, 0).total_m));
        for (size_t k = 0; k < c.size(); ++k)
            out.direct_max_relative = std::max(out.direct_max_relative, (c[k] - d[k]).norm() / d[k].norm());
    }
    out.speeds_checked = static_cast<int>(speeds.size());
}

std::vector<std::string> response_notes(const ExcitationSpec& x) {
    std::vector<std::string> notes{
        "forced response at the beam level: modal superposition in the modes at rest with the gyroscopic coupling of "
        "the spinning beams projected, checked against the direct solve of the full network",
        "damping in the stationary frame (bearings, air, web), per mode at rest (ratios, Rayleigh's alpha M + beta K); "
        "no rotating (internal) damping, no loss factors per part",
        "amplitude: the orbit's semi-major axis of the axis' total displacement (the bow's runout included: what a laser "
        "sees, less the surface's own out-of-roundness), summed over the orders (the largest excursion when their "
        "phases align)"};
    if (x.gravity)
        notes.push_back("gravity: the static sag is reported, not counted as vibration");
    if (x.ovality_m > 0 && !x.gravity)
        notes.push_back("[excitation] ovality without gravity excites nothing at the beam level (gravity = false)");
    return notes;
}

// What the run assumed beyond the file, each with its source (summary.json, report.md).
std::vector<std::string> setup_assumptions(const ResponseSetup& setup) {
    const ExcitationSpec& x = setup.excitation;
    std::vector<std::string> out;
    if (setup.response.limit_m == kDefaultAmplitudeLimit)
        out.push_back("amplitude limit 5 mm at " + setup.response.probes.front().name +
                      ": the default, Ilomaki's +-5 mm at mid-span (DOMAIN.md section 7)");
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
    if (!setup.damping.rayleigh || !setup.damping.families.empty() || !setup.damping.modes.empty())
        out.push_back(ModalDamping::kName);
    if (setup.damping.rayleigh) out.push_back(RayleighDamping::kName);
    for (const std::string& e : excitation_effect_names(x)) out.push_back(e);
    return out;
}

// The largest amplitude at the first probe, on the grid or on a refined peak.
void set_largest_amplitude(ResponseResult& out) {
    for (const ResponsePoint& p : out.points)
        if (p.probes[0].total_m > out.max_amplitude_m) out.max_amplitude_m = p.probes[0].total_m, out.max_amplitude_web_speed_m_s = p.web_speed_m_s;
    for (const ResponsePeak& p : out.peaks)
        if (p.amplitude_m > out.max_amplitude_m) out.max_amplitude_m = p.amplitude_m, out.max_amplitude_web_speed_m_s = p.web_speed_m_s;
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

ResponseResult run_forced_response(const Scene& scene, const ResponseSetup& setup, const BeamModelOptions& options) {
    if (scene.model != "beam")
        throw InputError(scene.source_file + ": [response] is simulated at the beam level only so far; expected model = "
                                             "\"beam\" (or --model beam); the solid and harmonic levels have no forced "
                                             "response yet");
    Stopwatch clock;
    ResponseResult out;
    const ResponseRange& range = setup.response;
    out.probes = range.probes, out.limit_m = range.limit_m, out.from_web_speed = range.from_web_speed;
    out.damping = setup.damping, out.damping_summary = damping_summary(setup.damping);
    out.roll_outer_diameter = roll_outer_diameter(scene);
    out.effects = effect_names(scene, setup);
    out.notes = response_notes(setup.excitation);
    // 1. At rest.
    const BeamModelResult rest = solve_beam_model(scene, options);
    const double f1 = first_bending_hz(rest);
    out.speeds_at_rest = roll_speeds(scene, f1, f1 > 0 ? "" : "no bending mode");
    // 2. The lateral problem, its modes, their damping and the loads.
    LateralResponse lateral(rest.network, rest.lambda_scale);
    const LateralDampingPlan damping = plan_damping(setup.damping, rest, lateral);
    lateral.set_damping(damping.rayleigh, damping.zeta);
    out.n_dofs = lateral.matrices().K.rows();
    const Eigen::VectorXd first_shape =
        setup.excitation.bow_shape == BowShape::first_mode ? first_bending_shape(rest) : Eigen::VectorXd();
    const ResponseLoads loads = build_response_loads(scene, setup.excitation, rest.network, lateral, first_shape);
    COREMODAL_ASSERT(!loads.orders.empty());  // the reader refuses an [excitation] that excites nothing
    out.assumptions = setup_assumptions(setup);
    for (const std::string& a : damping.assumptions) out.assumptions.push_back(a);
    for (const std::string& a : loads.assumptions) out.assumptions.push_back(a);
    for (const OrderLoad& l : loads.orders) out.orders.push_back(l.order), out.order_sources.push_back(l.sources);
    std::vector<CorePoint> probes;
    for (const ResponseRange::Probe& p : range.probes) probes.push_back(core_point(rest.network, p.z_m));
    if (loads.sag.size() > 0)
        for (int k = 0; k < 3; ++k) out.sag_m += probes[0].shape[k] * loads.sag(beam_dof::per_node * probes[0].nodes[k]);
    out.sag_m = std::abs(out.sag_m);
    out.ovality_split = loads.ovality_split;
    // 3. The sweep, with the modes up to kTruncationFactor times the highest load frequency.
    const double top_hz = out.orders.back() * range.speeds_hz.back();
    out.checks.n_modes_all = lateral.n_modes();
    out.checks.cutoff_hz = kTruncationFactor * top_hz;
    const int n_used = std::max(std::min(2, lateral.n_modes()), lateral.modes_below(2 * M_PI * out.checks.cutoff_hz));
    out.checks.n_modes_used = n_used;
    out.mode_damping.assign(damping.modes.begin(), damping.modes.begin() + n_used);
    const Evaluator eval(lateral, loads, probes, n_used);
    out.points = sweep(eval, range.speeds_hz, out.roll_outer_diameter);
    // 4. Peaks and the speed at the limit.
    out.peaks = find_peaks({eval, lateral, loads, rest, n_used, out.roll_outer_diameter}, out.points);
    out.safe = safe_speed(eval, out.points, out.peaks, range.limit_m, f1, out.roll_outer_diameter);
    set_largest_amplitude(out);
    // 5. The checks.
    check(eval, out.points, out.peaks, out.checks);
    out.assumptions.push_back("modes kept: " + std::to_string(n_used) + " of " + std::to_string(lateral.n_modes()) +
                              " lateral modes at rest, up to " + significant(out.checks.cutoff_hz, 4) + " Hz (" +
                              significant(kTruncationFactor, 2) +
                              " x the highest load frequency), with the static part of the others");
    out.solve_seconds = clock.lap();
    return out;
}

}  // namespace coremodal
