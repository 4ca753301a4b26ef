// The named terms of a structural operator set. Every kernel, coupling and
// assembled matrix says which term it belongs to, so that an effect that adds
// a new kind of term (rotation's gyroscopic matrix, a prestress's geometric
// stiffness, damping) plugs into the same cell loop and the same solver
// instead of widening every interface from (K, M) to (K, M, G, ...).
//
//   M q'' + (D + Omega G) q' + (K + K_sigma + Omega^2 K_Omega + i H) q = 0
//
// (i H: a loss independent of frequency, in the frequency domain only.)
//
// Stiffness and mass are always present; the others only when the scene
// names an effect that produces them (DESIGN.md "Effects on demand").
// Plain C++: no Eigen, PETSc or MPI, so that every stage can name a term.
#pragma once

#include <array>

namespace coremodal {

enum class Term {
    stiffness,            // K: elastic stiffness, springs, bearings
    mass,                 // M: consistent mass, lumped frame masses
    geometric_stiffness,  // K_sigma: stiffness of a prestress (centrifugal, web tension, gravity)
    gyroscopic,           // G: skew-symmetric, multiplied by the spin speed Omega
    centrifugal,          // K_Omega: symmetric, multiplied by Omega^2 (effects/rotation.hpp: the
                          // centrifugal prestress's geometric stiffness less the spin softening)
    damping,              // D: viscous damping
    imaginary_stiffness,  // H: the imaginary part of a complex stiffness K + i H, a loss that does
                          // not depend on frequency (which damping gives it: effects/damping.hpp)
};

inline constexpr std::array<Term, 7> kAllTerms = {Term::stiffness,   Term::mass,
                                                  Term::geometric_stiffness, Term::gyroscopic,
                                                  Term::centrifugal, Term::damping,
                                                  Term::imaginary_stiffness};

// "stiffness", "mass", "geometric stiffness", "gyroscopic", "centrifugal", "damping", "imaginary stiffness".
constexpr const char* term_name(Term t) {
    switch (t) {
        case Term::stiffness: return "stiffness";
        case Term::mass: return "mass";
        case Term::geometric_stiffness: return "geometric stiffness";
        case Term::gyroscopic: return "gyroscopic";
        case Term::centrifugal: return "centrifugal";
        case Term::damping: return "damping";
        case Term::imaginary_stiffness: return "imaginary stiffness";
    }
    return "?";
}

// Terms whose presence turns K x = lambda M x into a quadratic eigenproblem
// (an imaginary stiffness keeps it linear, but complex: neither solves it
// with an inertia count; only the projected damped solver takes it).
constexpr bool makes_problem_quadratic(Term t) { return t == Term::gyroscopic || t == Term::damping; }

}  // namespace coremodal
