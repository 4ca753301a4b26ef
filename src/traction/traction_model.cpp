#include "traction/traction_model.hpp"

#include "common/error.hpp"
#include "common/format.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace coremodal {
namespace {

// Five-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree 9.
constexpr std::array<double, 5> kGaussNodes = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                               0.9061798459386640};
constexpr std::array<double, 5> kGaussWeights = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                                 0.2369268850561891, 0.2369268850561891};

// The gap across one groove, from its edge (y = 0) to its other edge (y = G_W),
// without the asperities: the groove's own depth below the land.
double groove_depth_at(const Grooves& g, double y) {
    switch (g.shape) {
        case GrooveShape::none:
            return 0.0;
        case GrooveShape::sine:  // one cosine dip, G_D deep: amplitude G_D / 2 (docs/how-to/traction.md, eq. 16)
            return 0.5 * g.depth * (1.0 - std::cos(2.0 * std::numbers::pi * y / g.width));
        case GrooveShape::circular: {  // a circle of radius r_tool whose lowest point is G_D deep {18}
            const double x = y - 0.5 * g.width;
            const double r = g.tool_radius;
            return std::max(0.0, std::sqrt(std::max(0.0, r * r - x * x)) - r + g.depth);
        }
        case GrooveShape::rectangular:
            return g.depth;
    }
    return 0.0;
}

}  // namespace

double combined_asperity_height(double roller, double web) { return std::hypot(roller, web); }

double cube_mean_gap(const std::function<double(double)>& gap, double l, int panels) {
    COREMODAL_ASSERT(l > 0 && panels > 0);
    const double h = l / panels;
    double sum = 0;
    for (int p = 0; p < panels; ++p) {
        const double mid = (p + 0.5) * h;
        for (std::size_t i = 0; i < kGaussNodes.size(); ++i) {
            const double gy = gap(mid + 0.5 * h * kGaussNodes[i]);
            sum += kGaussWeights[i] * 0.5 * h * gy * gy * gy;
        }
    }
    return std::cbrt(sum / l);
}

double circular_groove_effective_depth(const Grooves& g, double offset) {
    return cube_mean_gap([&](double y) { return offset + groove_depth_at(g, y); }, g.width);
}

EffectiveClearance effective_clearance(const TractionSpec& spec) {
    EffectiveClearance out;
    const double alpha = combined_asperity_height(spec.roller_roughness, spec.web_roughness);
    out.asperity_height = alpha;
    const Grooves& g = spec.grooves;
    if (g.shape == GrooveShape::none) {
        out.clearance = alpha;  // {6}: the asperity engagement height is h_eff of a plain roller
        return out;
    }
    if (g.shape != GrooveShape::sine)  // {17}/{18}: the paper's effective groove depth, asperities left out
        out.groove_depth_eff = circular_groove_effective_depth(g, 0.0);
    // {8} over one pitch: the groove (its depth plus alpha) and the land (alpha).
    // With alpha = 0 this is {16} (sine, G_W = pitch) or {19}.
    const double groove = circular_groove_effective_depth(g, alpha);
    const double cube = (g.width * groove * groove * groove + g.land_width() * alpha * alpha * alpha) / g.pitch;
    out.clearance = std::cbrt(cube);
    return out;
}

double foil_bearing_gap(double radius, double viscosity, double speed_sum, double tension) {
    return kFoilGapFactor * radius * std::pow(6.0 * viscosity * speed_sum / tension, 2.0 / 3.0);
}

double contact_air_pressure(double radius, double viscosity, double speed_sum, double clearance) {
    if (speed_sum == 0) return 0.0;  // at rest no air is dragged in, however small h_eff (no 0 x inf)
    return kFoilPressureFactor * viscosity * speed_sum / radius * std::pow(radius / clearance, 1.5);
}

TractionPoint traction_at(const TractionSpec& spec, const EffectiveClearance& h, double web_speed) {
    COREMODAL_ASSERT(h.clearance > 0 && spec.roller_radius > 0 && spec.wrap > 0);
    TractionPoint p;
    const double R = spec.roller_radius;
    p.web_speed = web_speed;
    p.tension = spec.tension - spec.web_thickness * spec.web_density * web_speed * web_speed;
    COREMODAL_ASSERT(p.tension > 0);  // the reader refuses speeds at or above centripetal_limit_speed
    // The roller runs with the web (impending slip, no creep): V = V_r + V_w = 2 V_w.
    const double speed_sum = 2.0 * web_speed;
    p.wrap_pressure = p.tension / R;
    const double free_pressure = contact_air_pressure(R, spec.air_viscosity, speed_sum, h.clearance);
    p.p_star = free_pressure / p.wrap_pressure;                            // {10}
    p.h_star = foil_bearing_gap(R, spec.air_viscosity, speed_sum, p.tension) / h.clearance;  // {9}
    p.contact = p.p_star < 1.0;
    p.air_pressure = p.contact ? free_pressure : p.wrap_pressure;        // {11}
    p.contact_pressure = p.wrap_pressure - p.air_pressure;
    p.air_share = p.air_pressure / p.wrap_pressure;
    const double grip = 1.0 - std::exp(-spec.friction * spec.wrap);      // (e^(f theta) - 1) / e^(f theta)
    p.traction = p.contact_pressure * R * grip;                          // {13}, T_high held
    p.capstan_traction = p.tension * grip;                               // {1}
    p.effective_friction = std::log(spec.tension / (spec.tension - p.traction)) / spec.wrap;  // {15} via {2}

    const Grooves& g = spec.grooves;
    if (g.shape == GrooveShape::none) return p;
    if (p.contact) {  // {20}: undefined once the web floats (T/R - P_a = 0)
        const double alpha = h.asperity_height;
        const double lw = g.land_width();
        p.theta_star = alpha > 0 ? spec.air_viscosity * lw * lw * g.land_fraction() * web_speed /
                                       (2.0 * R * spec.wrap * alpha * alpha * p.contact_pressure)
                                 : (lw > 0 && web_speed > 0 ? std::numeric_limits<double>::infinity() : 0.0);
        if (*p.theta_star >= kMaxThetaStar)
            p.violations.push_back("theta* = " + significant(*p.theta_star, 3) + " >= " +
                                   significant(kMaxThetaStar) +
                                   " (eq. 20): low wrap for this land width; the air on the lands has no time to "
                                   "escape into the grooves and the model over-predicts traction");
    }
    if (spec.web_modulus && spec.web_poisson) {  // {21}
        const double c = spec.web_thickness;
        const double nu = *spec.web_poisson;
        const double D = *spec.web_modulus * c * c * c / (12.0 * (1.0 - nu * nu));
        p.b_star = p.wrap_pressure * std::pow(g.pitch, 4) / (c * D);
        if (*p.b_star >= kMaxBStar)
            p.violations.push_back("B* = " + significant(*p.b_star, 3) + " >= " + significant(kMaxBStar) +
                                   " (eq. 21): the web is thin for this groove pitch and sags into the grooves");
    }
    const double aspect = (g.depth / g.width) * (g.depth / g.width);
    if (aspect > kMaxLocalFlowError)
        p.violations.push_back("(G_D/G_W)^2 = " + significant(aspect, 3) + " > " + significant(kMaxLocalFlowError) +
                               ": grooves too deep for their width for eq. 8's local flow");
    p.valid = p.violations.empty();
    return p;
}

double slip_speed(const TractionSpec& spec, double needed) {
    const EffectiveClearance h = effective_clearance(spec);
    const double R = spec.roller_radius;
    // P_a R = k V_w while the web touches (V = 2 V_w in {5}).
    const double k = 2.0 * kFoilPressureFactor * spec.air_viscosity * std::pow(R / h.clearance, 1.5);
    const double grip = 1.0 - std::exp(-spec.friction * spec.wrap);
    const double margin = spec.tension - needed / grip;  // T_0 - c rho V^2 - k V must stay above needed / grip
    if (margin <= 0) return 0.0;
    const double m = spec.web_thickness * spec.web_density;
    // m V^2 + k V - margin = 0; the form without cancellation (m may be 0).
    return 2.0 * margin / (k + std::sqrt(k * k + 4.0 * m * margin));
}

double zero_traction_speed(const TractionSpec& spec) { return slip_speed(spec, 0.0); }

double centripetal_limit_speed(const TractionSpec& spec) {
    const double m = spec.web_thickness * spec.web_density;
    return m > 0 ? std::sqrt(spec.tension / m) : std::numeric_limits<double>::infinity();
}

std::vector<std::string> traction_model_assumptions(const TractionSpec& spec) {
    std::vector<std::string> out = {
        "the steady (constant-gap) region of the foil bearing covers the wrap; the entrance and exit regions are "
        "ignored (moderate to large wrap angles)",
        "the roller runs with the web (impending slip): V = V_r + V_w = 2 V_w in eqs. 3-5",
        "T_high is held (eq. 13, the traction tester's condition): Delta T = (T_high - P_a R)(1 - e^(-f theta)); "
        "T = T_0 - c rho V_w^2 (the centripetal term)",
        "the air is incompressible; air shear on the web is neglected (Ducotey & Good); the asperities are rigid",
        "the web is a membrane along the roller and rigid across it; the air has a continuous path from the inlet "
        "to the outlet nip through the surfaces' valleys (roughness valleys connected, grooves circumferential)",
        "contact and air pressure act over the same area R theta W; friction f does not depend on the load",
    };
    if (spec.grooves.shape != GrooveShape::none)
        out.push_back("the asperity height alpha is added to the local gap over lands and grooves in eq. 8 (our "
                      "reading: the paper leaves alpha out of a grooved roller's h_eff as small against G_D; with "
                      "alpha = 0 its printed clearances are ours)");
    return out;
}

const char* groove_shape_name(GrooveShape s) {
    switch (s) {
        case GrooveShape::none:
            return "none";
        case GrooveShape::sine:
            return "sine";
        case GrooveShape::circular:
            return "circular";
        case GrooveShape::rectangular:
            return "rectangular";
    }
    return "none";
}

}  // namespace coremodal
