// Beam theory of a core with rest paper: the comparison every FE result is
// set against (DOMAIN.md section 3, formula I-7 with k = 1).
#pragma once

#include "scene/scene.hpp"

#include <vector>

namespace coremodal {

// beta1 * L for the first bending mode of a clamped–clamped (= free–free) beam.
constexpr double kBeta1L = 4.730040744862704;

// Section properties of the core (and rest paper) as one beam. Bending uses
// the axial moduli E_z; shear uses the wall's in-plane shear modulus G_thetaz,
// which carries the transverse shear force of a tube (the wall is tangent to
// the load at the neutral axis), with Cowper's shear coefficient of a hollow
// circle.
struct BeamSection {
    double EI = 0;        // N m^2
    double rho_A = 0;     // kg/m
    double rho_I = 0;     // kg m (rotary inertia per length)
    double kappa_GA = 0;  // N
};

BeamSection beam_section(const Scene& scene);

// Cowper's shear coefficient of a hollow circular section (ri/ro = ratio).
double cowper_hollow_circle(double nu, double radius_ratio);

// First bending frequency (Hz) of an Euler–Bernoulli beam of span L,
// clamped–clamped or free–free (same beta1 L): formula I-7 with k = 1.
double euler_bernoulli_first_bending_hz(const BeamSection& s, double span_m);

enum class BeamEnds { clamped_clamped, free_free };

// Bending frequencies (Hz, ascending, rigid-body modes left out) of a
// Timoshenko beam (shear deformation and rotary inertia), by a converged
// finite-element model: 3-node elements, reduced integration of the shear
// term against locking; 80 elements put the first five frequencies within
// 1e-6 of the exact Timoshenko values.
std::vector<double> timoshenko_bending_hz(const BeamSection& s, double length_m, BeamEnds ends, int n_modes);

// The span a scene's first bending mode is compared with: the core length
// for a free scene, the distance between the inner edges of the clamp zones
// for a clamped one.
double beam_span(const Scene& scene);

}  // namespace coremodal
