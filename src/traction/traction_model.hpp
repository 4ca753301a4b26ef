// Web-to-roller traction: whether a web holds on a roller at speed, after
// B. S. Rice and R. F. Gans, "A simple model to predict web-to-roller
// traction" (Eastman Kodak Company / University of Rochester; equation
// numbers {n} below are the paper's). docs/how-to/traction.md gives the theory, our
// reading of each equation and the validity limits.
//
// The air dragged into the gap between web and roller carries part of the
// web's wrap pressure T/R; only the rest, T/R - P_a, presses the web onto
// its roller and makes friction. P_a is the foil-bearing pressure of the
// steady region with the gap replaced by the effective clearance h_eff of the
// rough (and perhaps grooved) surfaces in contact.
//
// Plain functions on SI values: no PETSc, no TOML. The case reader
// (scene/case_reader_traction.cpp) checks the inputs; these functions assume
// they were checked (positive radius, wrap, tension, viscosity, h_eff).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The source, as every output cites it (the text we hold names no venue or year).
inline constexpr const char* kRiceGansCitation =
    "B. S. Rice (Eastman Kodak Company) and R. F. Gans (University of Rochester), \"A simple model to predict "
    "web-to-roller traction\"";

// Foil-bearing constants of Eshel & Elrod (1965), quoted by Rice & Gans:
// the steady gap h = 0.643 R (6 mu V / T)^(2/3) {3}, inverted to the
// pressure P_a = 3.094 mu V / R (R / h)^(3/2) {4}; 3.094 = 6 x 0.643^(3/2).
inline constexpr double kFoilGapFactor = 0.643;
inline constexpr double kFoilPressureFactor = 3.094;
// Air at room temperature, the paper's Table 3: mu_a = 1.81e-5 N s/m^2.
inline constexpr double kAirViscosity = 1.81e-5;  // Pa s
// The paper's validity limits (its section "Limiting conditions"):
// theta* < 0.1 {20}: the air on the lands has time to escape into the grooves
// ("high wrap"); B* < 38.4 {21}: the web is rigid across a groove (deflection
// under 10 % of its thickness).
inline constexpr double kMaxThetaStar = 0.1;
inline constexpr double kMaxBStar = 38.4;
// Eq. 8 takes the flow as local (plane Poiseuille in each slice dy); Rice &
// Gans state its error is of order (G_D/G_W)^2. We flag a groove whose
// (G_D/G_W)^2 exceeds 0.1, the same 10 % the paper allows its other groups.
inline constexpr double kMaxLocalFlowError = 0.1;

// The roller's circumferential grooves, by cross-section.
enum class GrooveShape {
    none,         // a plain (non-grooved) roller: h_eff is the asperity height {6}
    sine,         // a flat web on a sine-wave surface {16} (the paper's roller 3)
    circular,     // grooves cut by a round tool: a circular segment {18}, then {19} (roller 4)
    rectangular,  // rectangular grooves: {19} with G_Deff = G_D
};

struct Grooves {
    GrooveShape shape = GrooveShape::none;
    double depth = 0;        // m, G_D: the groove's full depth, land (or crest) to bottom
    double width = 0;        // m, G_W: width of one groove at the land (sine: the pitch unless given)
    double pitch = 0;        // m, 1/N: groove to groove
    double tool_radius = 0;  // m, r_tool: circular grooves only

    double land_width() const { return pitch - width; }              // L_W
    double land_fraction() const { return land_width() / pitch; }    // L_F = L_W / (L_W + G_W)
};

// One roller and the web on it: the inputs of the model, in SI units.
struct TractionSpec {
    double roller_radius = 0;     // m, R
    double wrap = 0;              // rad, theta
    Grooves grooves;              // none by default
    double roller_roughness = 0;  // m, alpha_r: the roller's asperity engagement height (Rice et al. 2002)
    double web_roughness = 0;     // m, alpha_w: the web's
    double tension = 0;           // N/m, T_0 = T_high0: the nominal (high-side) tension per unit width
    double friction = 0;          // f: static coefficient of friction web on roller
    double air_viscosity = kAirViscosity;  // Pa s, mu
    double web_thickness = 0;              // m, c
    double web_density = 0;                // kg/m^3, rho
    std::optional<double> web_modulus;     // Pa, E: for B* {21} (grooved rollers)
    std::optional<double> web_poisson;     // nu: for B* {21}
    // N/m: the tension difference the roller must carry (a drive or brake);
    // when set, the speed at which it slips is reported too.
    std::optional<double> tension_difference;
    std::vector<double> web_speeds;  // m/s, increasing, V_w
};

// The effective web-to-roller clearance h_eff and what it is made of.
struct EffectiveClearance {
    double asperity_height = 0;                // m, alpha {6}
    std::optional<double> groove_depth_eff;    // m, G_Deff {17}/{18} (circular, rectangular)
    double clearance = 0;                      // m, h_eff
};

// alpha = sqrt(alpha_r^2 + alpha_w^2) {6}: Rice et al.'s root-mean-square
// combination of the two surfaces' asperity engagement heights.
double combined_asperity_height(double roller, double web);

// h_eff = [ (1/l) int_0^l h(y)^3 dy ]^(1/3) {8} of a gap profile h(y) >= 0
// sampled by `gap` on [0, l] (Gauss-Legendre; exact for polynomials of
// degree <= 9 on each of `panels` panels).
double cube_mean_gap(const std::function<double(double)>& gap, double l, int panels = 64);

// G_Deff {18}: the rectangular groove of the same flow as a circular segment
// cut G_D deep by a tool of radius r_tool, over the groove width G_W;
// `offset` is added to the local gap (our asperity height on the groove's
// bottom; 0 gives the paper's {18}).
double circular_groove_effective_depth(const Grooves& g, double offset = 0);

// h_eff of the roller and web: {6} for a plain roller; for a grooved one
// {16} or {18}+{19} with the asperity height alpha added to the local gap
// everywhere (lands and grooves: our reading, docs/how-to/traction.md), so that
// alpha -> 0 gives the paper's printed clearances and G_D -> 0 the plain
// roller's alpha.
EffectiveClearance effective_clearance(const TractionSpec& spec);

// The steady gap of a smooth foil bearing {3}: h = 0.643 R (6 mu V / T)^(2/3),
// V = V_r + V_w the sum of the surface speeds (m/s), T the tension (N/m).
double foil_bearing_gap(double radius, double viscosity, double speed_sum, double tension);
// The inverted contact foil bearing {5}: P_a = 3.094 mu V / R (R / h_eff)^(3/2), Pa
// (the pressure while the web still touches; {11} caps it at T/R).
double contact_air_pressure(double radius, double viscosity, double speed_sum, double clearance);

// Everything the model says at one web speed.
struct TractionPoint {
    double web_speed = 0;        // m/s, V_w (the roller's surface runs with it: V = 2 V_w)
    double tension = 0;          // N/m, T = T_0 - c rho V_w^2 (the centripetal term)
    double air_pressure = 0;     // Pa, P_a {11}
    double wrap_pressure = 0;    // Pa, T/R
    double contact_pressure = 0; // Pa, P_c = T/R - P_a
    double air_share = 0;        // P_a R / T: the share of the wrap pressure the air carries
    double p_star = 0;           // P* = P_a/(T/R) {10} before the cap ({11}): >= 1 means no contact
    double h_star = 0;           // h* = h/h_eff {9}
    double traction = 0;         // N/m, Delta T {13} with T_high held
    double capstan_traction = 0; // N/m, the same without air {1}: T (1 - e^(-f theta))
    double effective_friction = 0;  // f_e {15}
    std::optional<double> theta_star;  // {20}: grooved rollers while the web touches
    std::optional<double> b_star;      // {21}: grooved rollers with the web's E and nu
    bool contact = true;         // P* < 1
    bool valid = true;           // every group the point has within the paper's limits
    std::vector<std::string> violations;  // what is outside, in words
};

// The model at web speed V_w (m/s) for a roller and web of clearance h.
TractionPoint traction_at(const TractionSpec& spec, const EffectiveClearance& h, double web_speed);

// The web speed (m/s) at which the traction available falls to `needed`
// (N/m; 0: the zero-traction speed, P* = 1). From {13}: with T_high held,
// Delta T = (T_0 - c rho V_w^2 - P_a R)(1 - e^(-f theta)) and P_a R = k V_w,
// k = 2 x 3.094 mu (R/h_eff)^(3/2): the positive root of a quadratic.
// 0 when the roller cannot carry `needed` even at rest.
double slip_speed(const TractionSpec& spec, double needed);
// The speed at which traction vanishes (P* = 1, h* = 1): slip_speed(spec, 0).
// The one call the limits command needs for a scene's [traction] roller.
double zero_traction_speed(const TractionSpec& spec);

// The web speed at which the centripetal term c rho V_w^2 takes the whole
// tension T_0 (m/s; infinite for a massless web): above it the model has no
// meaning (the web no longer wraps the roller).
double centripetal_limit_speed(const TractionSpec& spec);

// The model's assumptions in words, as the paper states them (its section
// "Modified capstan equation") and as we apply them: echoed by every run.
std::vector<std::string> traction_model_assumptions(const TractionSpec& spec);

// "none", "sine", "circular", "rectangular".
const char* groove_shape_name(GrooveShape s);

}  // namespace coremodal
