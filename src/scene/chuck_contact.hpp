// Contact stiffness of an expanding element against the core bore, from the
// expansion pressure (docs/theory/chucks.md, "Interface stiffness").
//
// The core wall itself is in the model; what the spring layer adds is the
// compliance of the contact: the innermost plies and the surface roughness of
// the bore, a thin layer that stiffens with pressure like a paper stack.
// Pfeiffer's stack law p = K1 (exp(K2 eps) - 1) gives the tangent modulus
// E = dp/deps = K2 (p + K1); over a contact layer of thickness h the normal
// stiffness per unit area is
//     k_n = K2 (p + p_residual) / h,
// with p_residual the contact pressure that remains when the element is not
// expanded (the roll's weight on the chuck body spread over the contact).
// The tangential stiffness follows Mindlin's ratio for a stuck contact,
//     k_t / k_n = 2 (1 - nu) / (2 - nu).
// Every constant below is an assumption that the run summary echoes.
//
// A chuck that was not expanded (contact = "one-sided", docs/theory/chucks.md): the
// same law, with the pressure now the static contact pressure under gravity
// and K1 (here `residual_pressure`, the layer's stiffness scale at zero
// pressure) in its own role. Integrated, the stack law gives the pressure at
// an interpenetration d of the layer (d > 0 closed),
//     p(d) = K1 (exp(d / u0) - 1),   u0 = K1 / k_n0 = h / K2,
// and its tangent k_n(p) = dp/dd = k_n0 (1 + p / K1), with k_n0 the normal
// stiffness at zero pressure (the law's, or the case's normal_stiffness).
#pragma once

#include <cmath>
#include <string>

namespace coremodal {

// Sources and ranges of every constant: docs/reference/material-sources.md, "Chuck
// contact". The form k_n proportional to pressure is supported by rough-contact
// theory (Persson 2007: p ~ exp(-u/u0), so k_n = p/u0; Pastewka et al.:
// interfacial stiffness linear in p); K2 and h enter only as u0 = h/K2, for
// which no measurement against a core bore was found.
struct ContactLaw {
    // K2 (Pfeiffer). The "20-100 for paper stacks" has no source that could be
    // checked. With h: u0 = h/K2 = 20 um; suggested 5-50 um, i.e. k_n = 1.2e10
    // to 1.2e11 Pa/m at 6 bar. k is sensitive (case 08: 0.768, bonded 0.839).
    double stack_exponent = 50;
    double layer_thickness = 1e-3;     // h, m: one to two plies of the bore (see K2)
    // Two roles. contact = "uniform" with expanded = false: the residual
    // pressure of the old soft layer (not a material constant: the roll's
    // weight over the contact is 3-9 kPa for cases 07 and 09, 0.4-0.8 MPa for
    // a full 1 m news roll). contact = "one-sided": Pfeiffer's K1, the
    // stack's pressure scale (k_n0 = K2 K1 / h), the pressure itself being
    // computed; no source for K1 checked, suggested 5-50 kPa.
    double residual_pressure = 20e3;   // Pa
    // Mindlin's ratio holds for randomly rough contacts (Campana, Persson &
    // Mueser 2011); k_t/k_n = 0.67 (nu = 0.5) to 1.0 (nu = 0), 0.82 here.
    double poisson = 0.3;
    // No published chuck value found; the contact pressure of a bladder behind
    // leaves or lugs differs from the air pressure by their area ratio.
    double default_pressure = 0.6e6;   // Pa: a pneumatic element at 6 bar
};

inline const ContactLaw& contact_law() {
    static const ContactLaw law;
    return law;
}

// Normal stiffness per unit area (Pa/m) at expansion pressure p (Pa); p = 0
// for a chuck that was not expanded.
inline double contact_normal_stiffness(double p, const ContactLaw& law = contact_law()) {
    return law.stack_exponent * (p + law.residual_pressure) / law.layer_thickness;
}

inline double contact_tangential_ratio(const ContactLaw& law = contact_law()) {
    return 2 * (1 - law.poisson) / (2 - law.poisson);
}

// Standard gravity, m/s^2 (3rd CGPM, 1901; the local value is 9.780-9.832
// from equator to pole, a 0.5 % spread). The scene's gravity acts along -y.
constexpr double kStandardGravity = 9.80665;
inline const char* kGravityText = "9.80665 m/s^2 along -y";  // kStandardGravity, for the summary's words

// The one-sided contact's law at one point, from its stiffness at zero
// pressure k_n0 (Pa/m) and Pfeiffer's K1 (Pa).
struct StackContact {
    double k0 = 0;  // Pa/m, dp/dd at p = 0
    double K1 = 0;  // Pa

    double u0() const { return K1 / k0; }  // m: the layer's compression scale
    // Pressure at interpenetration d (m); 0 while open (d <= 0).
    double pressure(double d) const { return d > 0 ? K1 * std::expm1(d / u0()) : 0.0; }
    // Tangent stiffness at pressure p (Pa): k_n(p) = k_n0 (1 + p / K1).
    double stiffness(double p) const { return k0 * (1 + p / K1); }
};

// The assumptions a one-sided contact adds, echoed in the run's summary.
inline std::string one_sided_contact_assumption(const std::string& chuck, const ContactLaw& law = contact_law()) {
    return "chuck " + chuck +
           ": not expanded, one-sided contact: the bore rests on the chuck body across the radial clearance "
           "under gravity (" + std::string(kGravityText) + "; the roll's, chucks' and frames' weight), over the whole "
           "inserted length; compression only, p = K1 (exp(d/u0) - 1) with K1 = " +
           std::to_string(static_cast<int>(law.residual_pressure / 1e3)) +
           " kPa; static state frictionless (found by an active-set Newton iteration, 3D solid or coupled harmonics); the modes "
           "linearised about it: normal stiffness k_n0 (1 + p/K1) and tangential (Mindlin ratio) where the "
           "contact is closed (stuck: vibration below friction), nothing where open (docs/theory/chucks.md)";
}

}  // namespace coremodal
