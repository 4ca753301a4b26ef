#include "beam/formulas.hpp"

#include "beam/beam_theory.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace coremodal {
namespace {

constexpr double kPi = M_PI;
constexpr double kBeta1LSquared = kBeta1L * kBeta1L;  // 22.3733, "22.373" in I-7

// A value in a message, as printf's %g writes it.
std::string six_digits(double v) { return significant(v, 6); }

// Throws "<what> = <value> <unit> must be positive" for v <= 0 or not finite.
void require_positive(double v, const char* what, const char* unit) {
    if (!(v > 0) || !std::isfinite(v))
        throw InputError(std::string(what) + " = " + six_digits(v) + (*unit ? " " : "") + unit + " must be positive");
}

void require_factor(double v, const char* what) {
    if (!(v > 0 && v <= 1)) throw InputError(std::string(what) + " = " + six_digits(v) + " must lie in (0, 1]");
}

void check_section(const RestRollSection& s, bool with_paper) {
    require_positive(s.Di, "core inner diameter Di", "m");
    require_positive(s.Do, "core outer diameter Do", "m");
    if (s.Di >= s.Do)
        throw InputError("core inner diameter Di = " + six_digits(s.Di) +
                         " m must be smaller than the outer diameter Do = " + six_digits(s.Do) + " m");
    require_positive(s.Ec, "core modulus Ec", "Pa");
    require_positive(s.rho_c, "core density rho_c", "kg/m^3");
    if (s.Dp < s.Do)
        throw InputError("rest roll diameter Dp = " + six_digits(s.Dp) +
                         " m must be at least the core outer diameter Do = " + six_digits(s.Do) + " m");
    if (with_paper && s.Dp > s.Do) {
        require_positive(s.Ep, "rest paper modulus Ep", "Pa");
        require_positive(s.rho_p, "rest paper density rho_p", "kg/m^3");
    }
}

}  // namespace

double tube_area(double d_out, double d_in) {
    require_positive(d_out, "outer diameter", "m");
    if (!(d_in >= 0 && d_in < d_out))
        throw InputError("inner diameter = " + six_digits(d_in) +
                         " m must lie in [0, outer diameter = " + six_digits(d_out) + " m)");
    return kPi / 4 * (d_out * d_out - d_in * d_in);
}

double tube_inertia(double d_out, double d_in) {
    tube_area(d_out, d_in);  // checks
    return kPi / 64 * (std::pow(d_out, 4) - std::pow(d_in, 4));
}

double bending_stiffness(const RestRollSection& s) {
    check_section(s, true);
    double EI = s.Ec * tube_inertia(s.Do, s.Di);
    if (s.Dp > s.Do) EI += s.Ep * tube_inertia(s.Dp, s.Do);
    return EI;
}

double mass_per_length(const RestRollSection& s) {
    check_section(s, true);
    double m = s.rho_c * tube_area(s.Do, s.Di);
    if (s.Dp > s.Do) m += s.rho_p * tube_area(s.Dp, s.Do);
    return m;
}

// Ilomäki I-6, I-7: L = Lc - 2 Li.
double free_span(double Lc, double Li) {
    require_positive(Lc, "core length Lc", "m");
    if (!(Li >= 0) || !std::isfinite(Li))
        throw InputError("chuck distance Li = " + six_digits(Li) + " m must not be negative");
    if (Li >= Lc / 2)
        throw InputError("chuck distance Li = " + six_digits(Li) + " m must be less than half the core length Lc/2 = " +
                         six_digits(Lc / 2) + " m, or no free span is left");
    return Lc - 2 * Li;
}

// I-7.
double ilomaki_first_bending_hz(double EI, double rho_A, double L, double k) {
    require_positive(EI, "bending stiffness EcIc + EpIp", "N m^2");
    require_positive(rho_A, "mass per length rho_c Ac + rho_p Ap", "kg/m");
    require_positive(L, "free span L", "m");
    require_factor(k, "chuck factor k");
    return k * kBeta1LSquared / (2 * kPi) / (L * L) * std::sqrt(EI / rho_A);
}

double ilomaki_first_bending_hz(const RestRollSection& s, double L, double k) {
    return ilomaki_first_bending_hz(bending_stiffness(s), mass_per_length(s), L, k);
}

// I-6.
double chuck_factor(double f1_hz, double f2_hz) {
    require_positive(f1_hz, "clamped frequency f1", "Hz");
    require_positive(f2_hz, "free-free frequency f2", "Hz");
    return f1_hz / f2_hz;
}

// f2 = f_free Lc^2 / (Lc - 2 Li)^2 (Ilomäki I-6).
double free_free_at_free_span_hz(double f_free_hz, double Lc, double Li) {
    require_positive(f_free_hz, "free-hanging frequency f_free", "Hz");
    const double L = free_span(Lc, Li);
    return f_free_hz * Lc * Lc / (L * L);
}

// I-5.
double safe_web_speed(double f1_hz, double Dp, double safe) {
    require_positive(f1_hz, "first bending frequency f1", "Hz");
    require_positive(Dp, "rest roll diameter Dp", "m");
    require_factor(safe, "safety factor safe");
    return safe * kPi * Dp * f1_hz;
}

// I-14, dimensionless, so the same in mm or m.
double iso_free_free_shear_factor(double L, double Ic, double Ac) {
    require_positive(L, "sample length L", "m");
    require_positive(Ic, "core moment of inertia Ic", "m^4");
    require_positive(Ac, "core section area Ac", "m^2");
    return 82.66 * Ic / (Ac * L * L) + 1;
}

// I-13, evaluated in its own units (N/mm^2, kg/m, mm, mm^4).
double iso_flexural_modulus(double f_free_hz, double M, double L, double Ic, double Ac) {
    require_positive(f_free_hz, "free-free frequency f", "Hz");
    require_positive(M, "mass per length M", "kg/m");
    const double Q = iso_free_free_shear_factor(L, Ic, Ac);
    const double L_mm = L * 1e3, Ic_mm4 = Ic * 1e12;
    const double Ec_N_mm2 = 7.88e-8 * f_free_hz * f_free_hz * M * std::pow(L_mm, 4) * Q / Ic_mm4;
    return Ec_N_mm2 * 1e6;
}

// I-15: f = 22.373/(2 pi L^2) sqrt((EcIc + EpIp)/m)  =>  Ep = ((2 pi f L^2/22.373)^2 m - EcIc)/Ip.
double rest_paper_modulus(double f_free_hz, const RestRollSection& s, double L) {
    require_positive(f_free_hz, "free-free rest roll frequency f", "Hz");
    require_positive(L, "rest roll length L", "m");
    RestRollSection probe = s;
    probe.Ep = 1;  // Ep is what is sought; only the section check needs it
    check_section(probe, true);
    if (!(s.Dp > s.Do))
        throw InputError("rest roll diameter Dp = " + six_digits(s.Dp) +
                         " m must exceed the core outer diameter Do = " + six_digits(s.Do) +
                         " m to give a rest paper modulus");
    const double omega_term = 2 * kPi * f_free_hz * L * L / kBeta1LSquared;
    const double EcIc = s.Ec * tube_inertia(s.Do, s.Di);
    const double EI = omega_term * omega_term * mass_per_length(probe);
    if (EI <= EcIc)
        throw InputError("free-free rest roll frequency f = " + six_digits(f_free_hz) +
                         " Hz is at or below that of the core alone carrying the paper's mass, " +
                         six_digits(ilomaki_first_bending_hz(EcIc, mass_per_length(probe), L)) +
                         " Hz; the rest paper modulus Ep would not be positive");
    return (EI - EcIc) / tube_inertia(s.Dp, s.Do);
}

// K-1.
CriticalSpeed koenig_thin_rest_paper(double da, double di, double l, double E, double rho, double experience) {
    tube_area(da, di);
    require_positive(l, "free core length l", "m");
    require_positive(E, "core modulus E", "Pa");
    require_positive(rho, "core density rho", "kg/m^3");
    require_factor(experience, "experience factor");
    CriticalSpeed c;
    c.f_krit_hz = experience * 2.8 / kPi / (l * l) * std::sqrt(da * da + di * di) * std::sqrt(E / rho);
    c.v_krit_m_s = kPi * da * c.f_krit_hz;
    return c;
}

// K-2.
CriticalSpeed koenig_thick_rest_paper(const RestRollSection& s, double l, double experience) {
    require_positive(l, "free core length l", "m");
    require_factor(experience, "experience factor");
    CriticalSpeed c;
    c.f_krit_hz = experience * 11.2 / kPi / (l * l) * std::sqrt(bending_stiffness(s) / mass_per_length(s));
    c.v_krit_m_s = kPi * s.Dp * c.f_krit_hz;
    return c;
}

KoenigEstimate koenig_critical_speed(const RestRollSection& s, double l, double experience) {
    KoenigEstimate e;
    e.thin_paper = 0.5 * (s.Dp - s.Do) <= kKoenigThinLimit + 1e-12;
    e.speed = e.thin_paper ? koenig_thin_rest_paper(s.Do, s.Di, l, s.Ec, s.rho_c, experience)
                           : koenig_thick_rest_paper(s, l, experience);
    return e;
}

// I-1..I-4.
double damping_ratio_from_decay(double X0, double XN, double N) {
    require_positive(XN, "amplitude X_N", "");
    require_positive(N, "number of cycles N", "");
    if (!(X0 >= XN) || !std::isfinite(X0))
        throw InputError("amplitude X0 = " + six_digits(X0) +
                         " must be at least the later amplitude X_N = " + six_digits(XN) + " for a decay");
    return std::log(X0 / XN) / (2 * kPi * N);
}

double response_amplitude_ratio(double f_hz, double fn_hz, double zeta) {
    if (!(f_hz >= 0) || !std::isfinite(f_hz))
        throw InputError("excitation frequency f = " + six_digits(f_hz) + " Hz must not be negative");
    require_positive(fn_hz, "natural frequency fn", "Hz");
    if (!(zeta >= 0) || !std::isfinite(zeta))
        throw InputError("damping ratio zeta = " + six_digits(zeta) + " must not be negative");
    const double r = f_hz / fn_hz;
    const double denominator = std::sqrt(std::pow(1 - r * r, 2) + std::pow(2 * zeta * r, 2));
    if (denominator == 0)
        throw InputError("damping ratio zeta = 0 at resonance f = fn = " + six_digits(fn_hz) +
                         " Hz: the undamped response is unbounded");
    return 1 / denominator;
}

}  // namespace coremodal
