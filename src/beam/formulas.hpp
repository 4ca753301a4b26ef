// The quick formulas of the two source studies (docs/reference/references.md), as plain
// functions: SI units in and out (m, Pa, kg/m^3, kg/m, Hz, m/s). Each names its
// formula by its number: I-n from Ilomäki ("On the durability of
// cores and rest roll dynamics"), K-n from König & Müller (1988).
// Arguments outside a formula's domain throw InputError with a sentence naming
// the quantity and its value.
#pragma once

namespace coremodal {

// Section of a tube (docs/theory/beam.md, "Symbols"): A = pi/4 (Do^2 - Di^2),
// I = pi/64 (Do^4 - Di^4). Requires 0 <= d_in < d_out.
double tube_area(double d_out, double d_in);
double tube_inertia(double d_out, double d_in);

// A rest roll as the formulas see it: core Di/Do with Ec, rho_c; rest paper from
// Do to Dp with Ep, rho_p. A bare core has Dp = Do (Ep, rho_p then unused).
struct RestRollSection {
    double Di = 0, Do = 0, Dp = 0;  // m
    double Ec = 0, rho_c = 0;       // Pa, kg/m^3
    double Ep = 0, rho_p = 0;       // Pa, kg/m^3
};
// Ec Ic + Ep Ip (N m^2) and rho_c Ac + rho_p Ap (kg/m); check the section first.
double bending_stiffness(const RestRollSection& s);
double mass_per_length(const RestRollSection& s);

// Free span between the chucks, L = Lc - 2 Li (Ilomäki I-6, I-7).
// Requires Lc > 0 and 0 <= Li < Lc / 2.
double free_span(double Lc, double Li);

// I-7: f1 = k * 22.373/(2 pi) / L^2 * sqrt((Ec Ic + Ep Ip)/(rho_c Ac + rho_p Ap)).
// The first form takes EI = Ec Ic + Ep Ip (N m^2) and rho_A = rho_c Ac + rho_p Ap (kg/m).
// k = 1 is the clamped–clamped (= free–free) Euler–Bernoulli beam; k in (0, 1].
// 22.373 is used unrounded, (beta1 L)^2 = 4.7300407^2, as in beam_theory.hpp.
double ilomaki_first_bending_hz(double EI, double rho_A, double L, double k = 1.0);
double ilomaki_first_bending_hz(const RestRollSection& s, double L, double k = 1.0);

// I-6: chuck factor k = f1 / f2 (f1 clamped in the stand, f2 free–free at length L).
double chuck_factor(double f1_hz, double f2_hz);

// f2 from a free-hanging measurement at full length: f2 = f_free Lc^2/(Lc - 2 Li)^2.
double free_free_at_free_span_hz(double f_free_hz, double Lc, double Li);

// I-5: safe web speed v_safe = safe * pi * Dp * f1 (m/s). Ilomäki: safe 0.7–0.8
// (0.7 without a safety cage); values outside (0, 1] are refused.
double safe_web_speed(double f1_hz, double Dp, double safe = 0.7);

// I-13, I-14: flexural modulus from the ISO 11093-8 free–free test,
//   Ec = 7.88e-8 f^2 M L^4 Q / Ic,  Q = 82.66 Ic/(Ac L^2) + 1
// in N/mm^2 with M in kg/m, L in mm, Ic in mm^4, Ac in mm^2, the constant as
// published ((2 pi/22.373)^2 * 1e-6 = 7.887e-8 unrounded, so the published
// constant gives Ec 0.09 % lower than Euler–Bernoulli times Q). Here in SI: f in Hz,
// M in kg/m, L in m, Ic in m^4, Ac in m^2, Ec returned in Pa.
double iso_free_free_shear_factor(double L, double Ic, double Ac);  // Q (I-14)
double iso_flexural_modulus(double f_free_hz, double M, double L, double Ic, double Ac);  // I-13

// I-15: rest-paper modulus Ep from a free–free rest roll measurement of length L:
// I-7 with k = 1 solved for Ep (s.Ep is ignored). Throws when the measured
// frequency is at or below that of the bare core with the paper's mass (Ep <= 0).
double rest_paper_modulus(double f_free_hz, const RestRollSection& s, double L);

// K-1 and K-2: König's critical speed; the experience factor (0.66, fitted to
// exploded 76 mm cores; 0.55 recommended for the 150/176 core) in (0, 1].
struct CriticalSpeed {
    double f_krit_hz = 0;
    double v_krit_m_s = 0;
};
// K-1, rest paper up to 10 mm: f_krit = c * 2.8/pi / l^2 * sqrt(da^2 + di^2) * sqrt(E/rho),
// v_krit = pi * da * f_krit; da, di core outer/inner diameters, E, rho of the core,
// l = core length minus the chuck insertion depth at both ends.
CriticalSpeed koenig_thin_rest_paper(double da, double di, double l, double E, double rho,
                                     double experience = 0.66);
// K-2, thicker rest paper: f_krit = c * 11.2/pi / l^2 * sqrt((E_H I_H + Ep Ip)/(rho_H A_H + rho_p Ap)),
// v_krit = pi * dp * f_krit (core H = s.Di..s.Do with s.Ec, s.rho_c).
CriticalSpeed koenig_thick_rest_paper(const RestRollSection& s, double l, double experience = 0.66);
// The rest paper thickness up to which K-1 applies (König): 10 mm.
constexpr double kKoenigThinLimit = 0.010;
// König's formula for the section: K-1 up to kKoenigThinLimit of rest paper,
// else K-2 (thin_paper says which was used).
struct KoenigEstimate {
    CriticalSpeed speed;
    bool thin_paper = true;
};
KoenigEstimate koenig_critical_speed(const RestRollSection& s, double l, double experience = 0.66);

// I-1..I-4, damping: relative damping from a free decay over N cycles,
// zeta = ln(X0/XN)/(2 pi N); requires X0 >= XN > 0 and N > 0.
double damping_ratio_from_decay(double X0, double XN, double N);
// Forced-response amplitude ratio d(f) = 1/sqrt((1 - r^2)^2 + (2 zeta r)^2), r = f/fn.
double response_amplitude_ratio(double f_hz, double fn_hz, double zeta);

}  // namespace coremodal
