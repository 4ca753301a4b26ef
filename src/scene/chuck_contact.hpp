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

struct ContactLaw {
    double stack_exponent = 50;        // K2 (Pfeiffer): 20-100 for paper stacks
    double layer_thickness = 1e-3;     // h, m: one to two plies of the bore
    double residual_pressure = 20e3;   // p_residual, Pa: a not-expanded element
    double poisson = 0.3;              // nu in Mindlin's ratio
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
