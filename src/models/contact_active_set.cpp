#include "models/contact_active_set.hpp"

#include "common/error.hpp"
#include "common/format.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// The active set of a compliant contact settles in a few iterations; a set
// that keeps changing after this many is cycling.
constexpr int kMaxContactIterations = 60;
// Newton on an exponential law overshoots from a point closed at low
// pressure: no point may close further than this many u0 per step (the
// pressure rises at most e^3 = 20 times), the step is scaled down otherwise.
constexpr double kMaxClosingStep = 3.0;
// The first iterate closes the bore's top (within this angle of +y) at zero
// pressure. A wider start would overshoot: a spring linearised at d = 0
// pulls its point across the whole clearance, so closing the upper half
// would drop the core by 4c/pi and start the exponential law at d = 0.27 c
// (7 u0 at the defaults), far from the state.
constexpr double kFirstArc = 10 * M_PI / 180;
// Converged when the set repeats and no point moves by more than this
// fraction of u0 (20 um by default: 2e-13 m) in a full Newton step.
constexpr double kConvergedStep = 1e-8;
// ... or when Newton has reached the round-off of its solves: the set
// repeats, the full step is below this fraction of u0 (20 pm) and no longer
// shrinks tenfold (quadratic convergence shrinks it by orders). The floor
// depends on the machine's BLAS kernels: on a Zen 5 machine the rigid-core
// test's steps went 4.7e-5, 9.2e-8 and then wandered between 1.5e-8 and
// 9.2e-8 u0 for 55 iterations (tests/verification/test_one_sided_contact.cpp).
constexpr double kStagnantStep = 1e-6;
constexpr double kStagnantRatio = 0.1;

const OneSidedContact& contact_of(const SupportEffects& effects, const BorePoint& q) {
    return *effects.chucks.at(q.chuck).one_sided;
}

ContactIterate first_iterate(const std::vector<BorePoint>& points) {
    ContactIterate it;
    for (const BorePoint& q : points) {
        it.active.push_back(q.normal()[1] > std::cos(kFirstArc));
        it.d.push_back(0);
        it.p.push_back(0);
    }
    return it;
}

// The next iterate from the step's interpenetrations: damped so that no
// point closes by more than kMaxClosingStep u0 (not on the first step, whose
// iterate is a guess, not a state). Returns the full step's largest move, in u0.
double advance(ContactIterate& it, const std::vector<double>& d_new, const std::vector<BorePoint>& points,
               const SupportEffects& effects, bool first, double& alpha) {
    double closing = 0, moved = 0;
    for (size_t i = 0; i < d_new.size(); ++i) {
        const double u0 = contact_of(effects, points[i]).law.u0();
        closing = std::max(closing, (std::max(d_new[i], 0.0) - std::max(it.d[i], 0.0)) / u0);
        moved = std::max(moved, std::abs(d_new[i] - it.d[i]) / u0);
    }
    alpha = first || closing <= kMaxClosingStep ? 1.0 : kMaxClosingStep / closing;
    for (size_t k = 0; k < points.size(); ++k) {
        it.d[k] = first ? d_new[k] : it.d[k] + alpha * (d_new[k] - it.d[k]);
        it.active[k] = it.d[k] > 0;
        it.p[k] = contact_of(effects, points[k]).law.pressure(it.d[k]);
    }
    return moved;
}

// The rigid-motion stiffnesses of the closed contact (ChuckContactState).
void add_support_stiffness(const std::vector<BorePoint>& points, const std::vector<ContactPointState>& s,
                           const SupportEffects& effects, std::vector<ChuckContactState>& out) {
    for (size_t k = 0; k < points.size(); ++k) {
        const BorePoint& q = points[k];
        if (!s[k].closed()) continue;
        ChuckContactState& c = out[q.chuck];
        const Eigen::Matrix3d D = contact_of(effects, q).linearised(s[k].p).per_area(std::atan2(q.x[1], q.x[0]));
        const double z_mid = (c.z_from_m + c.z_to_m) / 2;
        const Eigen::Vector3d tilt(0, -(q.x[2] - z_mid), q.x[1]);  // e_x x (x - x_mid)
        c.vertical_stiffness_n_per_m += q.area_weight * D(1, 1);
        c.horizontal_stiffness_n_per_m += q.area_weight * D(0, 0);
        c.tilt_stiffness_nm_per_rad += q.area_weight * tilt.dot(D * tilt);
    }
}

std::vector<ChuckContactState> summarise(const std::vector<BorePoint>& points, const std::vector<ContactPointState>& s,
                                         const SupportEffects& effects) {
    std::vector<ChuckContactState> out(effects.chucks.size());
    std::vector<double> phi_lo(out.size(), M_PI), phi_hi(out.size(), -M_PI);
    for (size_t c = 0; c < out.size(); ++c) {
        out[c].chuck = effects.chucks[c].placement.chuck;
        out[c].z_from_m = INFINITY;
        out[c].z_to_m = -INFINITY;
    }
    for (size_t k = 0; k < points.size(); ++k) {
        const BorePoint& q = points[k];
        ChuckContactState& c = out[q.chuck];
        ++c.points;
        const ContactPointState& p = s[k];
        if (!p.closed()) continue;
        ++c.closed_points;
        const double phi = std::atan2(q.x[0], q.x[1]);  // from the top (+y), towards +x
        phi_lo[q.chuck] = std::min(phi_lo[q.chuck], phi);
        phi_hi[q.chuck] = std::max(phi_hi[q.chuck], phi);
        c.z_from_m = std::min(c.z_from_m, q.x[2]);
        c.z_to_m = std::max(c.z_to_m, q.x[2]);
        c.closed_area_m2 += q.area_weight;
        c.vertical_force_n += p.p * q.area_weight * q.normal()[1];
        c.max_pressure_pa = std::max(c.max_pressure_pa, p.p);
    }
    for (size_t c = 0; c < out.size(); ++c)
        if (out[c].closed_points > 0) out[c].arc_deg = (phi_hi[c] - phi_lo[c]) * 180 / M_PI;
    add_support_stiffness(points, s, effects, out);
    std::erase_if(out, [](const ChuckContactState& c) { return c.points == 0; });
    return out;
}

}  // namespace

Eigen::Vector3d static_contact_stiffness(const OneSidedContact& contact, const ContactIterate& it, size_t i) {
    if (!it.active[i]) return Eigen::Vector3d::Zero();
    const double k = contact.law.stiffness(it.p[i]);
    return {k, kStaticTangentialFraction * k, kStaticTangentialFraction * k};
}

double static_contact_traction(const OneSidedContact& contact, const ContactIterate& it, size_t i) {
    return it.active[i] ? it.p[i] - contact.law.stiffness(it.p[i]) * (it.d[i] + contact.clearance) : 0.0;
}

GravityContact solve_active_set(const std::vector<BorePoint>& points, const SupportEffects& effects,
                                const ContactNewtonStep& step, const Printer& say) {
    ContactIterate it = first_iterate(points);
    GravityContact out;
    double previous_move = INFINITY;
    for (int k = 1; k <= kMaxContactIterations; ++k) {
        const std::vector<char> before = it.active;
        const std::vector<double> d_new = step(it);
        COREMODAL_ASSERT(d_new.size() == points.size());
        for (double d : d_new)
            if (!std::isfinite(d))
                throw SolveError("the static solve under gravity gave a non-finite interpenetration: the roll is "
                                 "not held while its contact is open; check the clearance and the bearings");
        double alpha = 1;
        const double moved = advance(it, d_new, points, effects, k == 1, alpha);
        const int closed = static_cast<int>(std::count(it.active.begin(), it.active.end(), 1));
        out.closed_history.push_back(closed);
        say("      static contact, iteration " + std::to_string(k) + ": " + std::to_string(closed) + " of " +
            std::to_string(it.active.size()) + " points closed" + (alpha < 1 ? ", step " + significant(alpha) : ""));
        if (closed == 0)
            throw SolveError("the static solve under gravity opened every contact point: the roll no longer rests "
                             "on its chucks (is the clearance larger than the bore allows?)");
        const bool settled =
            moved < kConvergedStep || (moved < kStagnantStep && moved > kStagnantRatio * previous_move);
        previous_move = moved;
        if (k > 1 && it.active == before && alpha == 1 && settled) {
            out.iterations = k;
            for (size_t i = 0; i < it.d.size(); ++i) out.state.push_back({it.d[i], it.p[i]});
            out.chucks = summarise(points, out.state, effects);
            return out;
        }
    }
    throw SolveError("the contact under gravity did not settle in " + std::to_string(kMaxContactIterations) +
                     " active-set iterations (closed points per iteration cycle); expected a finer mesh or a "
                     "larger clearance");
}

std::vector<std::string> contact_state_lines(const GravityContact& contact, double roll_weight_n) {
    std::vector<std::string> lines;
    for (const ChuckContactState& c : contact.chucks)
        lines.push_back("chuck " + c.chuck + ": the static contact under gravity (" +
                        std::to_string(contact.iterations) + " active-set iterations; frictionless, held about the "
                        "axis by a tangential spring of " + significant(kStaticTangentialFraction, 1) +
                        " k_n) is closed over " +
                        significant(c.arc_deg, 3) + " deg of arc at the top and z = " + significant(c.z_from_m * 1e3, 4) +
                        " to " + significant(c.z_to_m * 1e3, 4) + " mm (" + std::to_string(c.closed_points) + " of " +
                        std::to_string(c.points) + " points), carries " + significant(c.vertical_force_n, 4) +
                        " N of the roll's " + significant(roll_weight_n, 4) + " N, peak pressure " +
                        significant(c.max_pressure_pa / 1e3, 3) + " kPa; holds the core by " +
                        significant(c.vertical_stiffness_n_per_m, 3) + " N/m vertically, " +
                        significant(c.horizontal_stiffness_n_per_m, 3) + " N/m sideways, " +
                        significant(c.tilt_stiffness_nm_per_rad, 3) + " N m/rad in tilt");
    return lines;
}

}  // namespace coremodal
