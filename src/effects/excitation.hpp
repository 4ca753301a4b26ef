// Excitation of a spinning roll ([excitation], docs/how-to/response.md), stated once
// for every model level; analyses/response puts the loads on the beam network
// (response_loads), on the harmonic level's wave number n = 1 (harmonic_loads)
// and on the solid's nodes (solid_loads).
//
//   effect           order  harmonic (n = 1) and solid (nodal forces)      beam
//   unbalance        1      U Omega^2 on the core's section at mid-core    U Omega^2 at mid-core
//   eccentricity     1      e Omega^2 M_rp r_x (the rest paper's cells)    rho_p A_p e Omega^2 per length
//   bow              1      K_roll u_bow, the roll's cells, element-wise   K_core u_bow
//   ovality_gravity  2      eps K_core u_sag (the core's cells)            eps K_EIc u_sag
//   gravity          0      the static sag (reported; not a vibration)      the same
//
// Frame and sign: stationary frame, the roll spins at Omega about +z; a load
// turning with it is Re(p e^{i k Omega t}) in x and Re(-i p e^{i k Omega t})
// in y (a vector of length |p| turning forward), for the y-z plane's
// rotation -rx as for the x-z plane's ry (timoshenko_element.hpp). The
// response is q = Re(x e^{i omega t}), omega = k Omega, of
//     (K - omega^2 M + i omega (Omega G + D)) x = f      (effects/damping.hpp: D)
//
// Unbalance (order 1). A mass m at radius e turning with the roll pulls on
// the axis with m e Omega^2 towards itself: U Omega^2, U = m e (kg m), a
// point force at mid-core [Den Hartog, Mechanical Vibrations, §3.4]. An
// eccentric rest roll, its mass centre e off the axis along its whole
// length, is the same per unit length: rho_p A_p e Omega^2 (the rest paper's
// mass per length, Ilomäki I-7), distributed with the elements' shape
// functions. Unbalance and bow are taken at the same angle (in phase): the
// assumption that adds their amplitudes where both drive the same mode.
//
// Bow (order 1). A bowed core is stress-free in its bowed shape u_bow (a
// half sine b sin(pi z / Lc) along the core, or the first bending mode at
// rest, scaled to b at mid-core; with the section rotations of the bowed
// axis, ry = d ux / dz, so that the bow itself is free of shear). With q the
// total displacement of the axis from the bearing line, the core's elastic
// force is K_core (q - u_bow) and every other part (chucks, clamps, springs)
// is straight when unloaded, so
//     M q'' + (Omega G + D) q' + K q = K_core u_bow      (turning with the roll)
// where K_core is the core beam's own stiffness (with the rest paper). The
// bow's mass eccentricity needs no term of its own: the inertia M q'' acts on
// the total displacement, in which the bowed axis is. The probe reports q,
// the total displacement including the bow's runout: what a laser on the
// roll's surface sees (less the out-of-roundness of the surface itself).
// At rest q is the bow where the supports let it be; far above the first
// critical speed the roll turns about its mass axis and q tends to 0 (the
// bowed rotor's self-centring) [Nicholas, Gunter & Allaire, "Effect of
// residual shaft bow on unbalance response", J. Eng. Ind. 98 (1976)].
//
// Ovality with gravity (order 2). An out-of-round core, radius
// r(theta) = R + delta cos 2 theta through the whole wall (delta = (D_max -
// D_min) / 4, the roundness deviation as a diameter difference), has the
// second moments of area, to first order in delta,
//     I_xx,yy = pi (Ro^4 - Ri^4) / 4 -+ (pi / 2) delta (Ro^3 - Ri^3)
// (integrate rho^3 sin^2 theta over rho = r + delta cos 2 theta, dA = rho dr
// dtheta), so its principal bending stiffnesses are E_c I_c (1 +- eps),
//     eps = 2 delta (Ro^3 - Ri^3) / (Ro^4 - Ri^4)      (-> 3 delta / (2R), thin wall).
// The rest paper is taken round (its layers wound under tension do not keep
// the core's ovality): only the core's E_c I_c splits. Turning with the
// roll, the stiffness in the stationary frame is K_mean + eps K_EIc [[cos 2
// Omega t, sin 2 Omega t], [sin, -cos]] per plane pair. Under gravity the roll
// hangs in its static sag u_sag (K u_sag = weight); the varying part acting
// on it is a force eps K_EIc u_sag turning forward at 2 Omega (in x + i y:
// i eps k s e^{2 i Omega t} for a sag s along -y). Taken to first order in eps
// (the response to it then acts on the varying stiffness again only at
// O(eps^2): the parametric instability of an asymmetric shaft is outside
// this model) [Genta, Dynamics of Rotating Systems, §6 (asymmetric rotors
// under gravity: the 2x "secondary critical")].
#pragma once

#include "scene/response_spec.hpp"

#include <string>
#include <vector>

namespace coremodal {

// Standard gravity, m/s^2 (CGPM 1901).
inline constexpr double kGravity = 9.80665;

struct Unbalance { static constexpr const char* kName = "unbalance"; };
struct Eccentricity { static constexpr const char* kName = "eccentricity"; };
struct Bow { static constexpr const char* kName = "bow"; };
struct OvalityGravity { static constexpr const char* kName = "ovality_gravity"; };
struct Gravity { static constexpr const char* kName = "gravity"; };

// eps above: the relative half-difference of the core's principal second
// moments of area for a roundness deviation D_max - D_min (m), outer and
// inner diameter Do, Di (m).
double ovality_stiffness_split(double ovality_m, double outer_diameter, double inner_diameter);

// The half-sine bow b sin(pi z / L) and its slope, z along the core (0..L).
double half_sine_bow(double bow_m, double z, double length);
double half_sine_bow_slope(double bow_m, double z, double length);

// The excitation's names in the summary's `effects` list, in the order of
// the table above: only what the scene gives (an ovality without gravity
// excites nothing at any level and is not listed).
std::vector<std::string> excitation_effect_names(const ExcitationSpec& excitation);

}  // namespace coremodal
