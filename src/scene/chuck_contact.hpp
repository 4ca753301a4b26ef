// Contact stiffness of an expanding element against the core bore, from the
// expansion pressure (docs/chucks.md, "Interface stiffness").
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
#pragma once

namespace coremodal {

// Sources and ranges of every constant: docs/material-sources.md, "Chuck
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
    // Not a material constant: the roll's weight over the contact is 3-9 kPa
    // for cases 07 and 09 and 0.4-0.8 MPa for a full 1 m news roll.
    double residual_pressure = 20e3;   // p_residual, Pa: a not-expanded element
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

}  // namespace coremodal
