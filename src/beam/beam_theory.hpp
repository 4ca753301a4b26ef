// Beam theory of a core with rest paper: the comparison every FE result is
// set against (Ilomäki I-7 with k = 1).
#pragma once

#include "beam/formulas.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace coremodal {

// beta1 * L for the first bending mode of a clamped–clamped (= free–free) beam.
constexpr double kBeta1L = 4.730040744862704;

// Section properties of the core (and rest paper) as one beam. Bending and
// stretching use the axial moduli E_z; shear uses the wall's in-plane shear
// modulus G_thetaz, which carries the transverse shear force of a tube (the
// wall is tangent to the load at the neutral axis), with Cowper's shear
// coefficient of a hollow circle; torsion shears the wall in the same
// theta-z plane, so GJ uses G_thetaz too. Layers add (no slip between them).
struct BeamSection {
    double EI = 0;        // N m^2, about either transverse axis
    double rho_A = 0;     // kg/m
    double rho_I = 0;     // kg m (rotary inertia per length, about a transverse axis)
    double kappa_GA = 0;  // N
    double EA = 0;        // N
    double GJ = 0;        // N m^2 (torsion; J = 2 I for a circular section)
    double rho_J = 0;     // kg m (polar inertia per length, = 2 rho_I)

    BeamSection& operator+=(const BeamSection& layer);
};

// One layer: a tube d_in..d_out (d_in = 0: a solid circle) of one material.
BeamSection tube_beam_section(double d_out, double d_in, const OrthotropicMaterial& material);

// The core, plus the rest paper when the scene has one.
BeamSection beam_section(const Scene& scene);

// The scene's rest roll as the quick formulas see it (Dp = Do without rest paper).
RestRollSection rest_roll_section(const Scene& scene);

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
// for a clamped one, Ilomäki's free span L = Lc - Li(left) - Li(right) for
// chucks (Li: core end to the middle of the furthest expanding element).
double beam_span(const Scene& scene);

}  // namespace coremodal
