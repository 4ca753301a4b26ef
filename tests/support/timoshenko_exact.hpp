// Exact frequencies of a uniform Timoshenko beam (shear deformation and
// rotary inertia), solved here from the equations of motion so that the
// finite-element beams are checked against something they do not share.
#pragma once

#include "beam/beam_theory.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <cmath>

namespace coremodal::testing {

// Exact Timoshenko frequency equation of a uniform beam, the textbook way:
//   rho A w_tt = kGA (w'' - phi'),  rho I phi_tt = EI phi'' + kGA (w' - phi).
// With w, phi ~ e^(lambda x) e^(i omega t):
//   EI kGA lambda^4 + (EI rhoA + rhoI kGA) omega^2 lambda^2 + rhoA omega^2 (rhoI omega^2 - kGA) = 0,
// a quadratic in lambda^2 with roots alpha^2 > 0 and -beta^2 < 0 below the
// cut-off omega^2 = kGA/rhoI. Then
//   w   = C1 cosh ax + C2 sinh ax + C3 cos bx + C4 sin bx
//   phi = p (C1 sinh ax + C2 cosh ax) + q (-C3 sin bx + C4 cos bx),
//   p = a + rhoA omega^2/(kGA a),  q = b - rhoA omega^2/(kGA b)
// (Euler–Bernoulli limit: p = a, q = b, phi = w'). The frequency makes the
// 4x4 matrix of the boundary conditions singular.
inline double boundary_determinant(const BeamSection& s, double L, BeamEnds ends, double omega) {
    const double w2 = omega * omega;
    const double a_ = s.EI * s.kappa_GA, b_ = (s.EI * s.rho_A + s.rho_I * s.kappa_GA) * w2,
                 c_ = s.rho_A * w2 * (s.rho_I * w2 - s.kappa_GA);
    const double root = std::sqrt(b_ * b_ - 4 * a_ * c_);
    const double a = std::sqrt((-b_ + root) / (2 * a_)), b = std::sqrt((b_ + root) / (2 * a_));
    const double p = a + s.rho_A * w2 / (s.kappa_GA * a), q = b - s.rho_A * w2 / (s.kappa_GA * b);
    // Rows: a condition at x; columns: C1..C4.
    auto w_row = [&](double x) {
        return Eigen::RowVector4d(std::cosh(a * x), std::sinh(a * x), std::cos(b * x), std::sin(b * x));
    };
    auto phi_row = [&](double x) {
        return Eigen::RowVector4d(p * std::sinh(a * x), p * std::cosh(a * x), -q * std::sin(b * x), q * std::cos(b * x));
    };
    auto moment_row = [&](double x) {  // phi' (bending moment / EI)
        return Eigen::RowVector4d(p * a * std::cosh(a * x), p * a * std::sinh(a * x), -q * b * std::cos(b * x),
                                  -q * b * std::sin(b * x));
    };
    auto shear_row = [&](double x) {  // w' - phi (shear force / kGA)
        return Eigen::RowVector4d((a - p) * std::sinh(a * x), (a - p) * std::cosh(a * x), (q - b) * std::sin(b * x),
                                  (b - q) * std::cos(b * x));
    };
    Eigen::Matrix4d M;
    if (ends == BeamEnds::clamped_clamped) M << w_row(0), phi_row(0), w_row(L), phi_row(L);
    else M << moment_row(0), shear_row(0), moment_row(L), shear_row(L);
    return M.determinant();
}

// First root of the determinant above from_share * f_EB: scan for a sign
// change up to 1.1 f_EB, then bisect (below the shear cut-off only).
inline double exact_timoshenko_first_hz(const BeamSection& s, double L, BeamEnds ends, double from_share = 0.5) {
    const double f_eb = euler_bernoulli_first_bending_hz(s, L);
    auto D = [&](double f) { return boundary_determinant(s, L, ends, 2 * M_PI * f); };
    const int steps = 2000;
    double lo = from_share * f_eb, d_lo = D(lo);
    for (int i = 1; i <= steps; ++i) {
        double hi = from_share * f_eb + i * ((1.1 - from_share) * f_eb / steps);
        if ((D(hi) < 0) == (d_lo < 0)) {
            lo = hi, d_lo = D(hi);
            continue;
        }
        while (hi - lo > 1e-14 * hi) {
            const double mid = 0.5 * (lo + hi), d_mid = D(mid);
            if ((d_mid < 0) == (d_lo < 0)) lo = mid, d_lo = d_mid;
            else hi = mid;
        }
        return 0.5 * (lo + hi);
    }
    FAIL("no root of the Timoshenko frequency equation between " << from_share << " and 1.1 f_EB");
    return 0;
}


// Simply supported (w = 0, bending moment = 0 at both ends): the m-th mode is
// w = W sin(k z), phi = P cos(k z), k = m pi / L, and the equations of motion give
//   [kGA k^2 - rhoA w^2,  -kGA k; -kGA k,  EI k^2 + kGA - rhoI w^2] (W, P) = 0,
// a quadratic in w^2 whose smaller root is the bending frequency.
inline double simply_supported_timoshenko_hz(const BeamSection& s, double L, int m) {
    const double k = m * M_PI / L;
    const double a = s.rho_A * s.rho_I;
    const double b = -(s.rho_A * (s.EI * k * k + s.kappa_GA) + s.rho_I * s.kappa_GA * k * k);
    const double c = s.kappa_GA * k * k * s.EI * k * k;
    const double w2 = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
    return std::sqrt(w2) / (2 * M_PI);
}

}  // namespace coremodal::testing
