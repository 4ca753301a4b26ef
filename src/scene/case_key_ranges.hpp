// The bounds and plausible ranges of the case-file keys (scene/case_keys.cpp),
// each with its reason and source. Included by the key table alone.
#pragma once

#include "scene/case_schema.hpp"

#include <cmath>
#include <limits>
#include <string_view>

namespace coremodal::key_ranges {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Upper bounds that catch unit slips (a plain 76 is 76 m, not 76 mm) rather
// than physics: no core or rest roll comes near them.
inline constexpr double kMaxDiameter = 5.0;  // m
inline constexpr double kMaxLength = 50.0;   // m
inline constexpr double kMaxModulus = 1e13;  // Pa, above diamond
inline constexpr double kMaxDensity = 1e5;   // kg/m^3, above osmium
inline constexpr int kMaxModes = 10000;
inline constexpr int kMaxElementsThrough = 100;
inline constexpr int kMaxElementsAround = 4096;
inline constexpr double kMaxWebSpeed = 100.0;  // m/s; presses run up to ~20 m/s
inline constexpr int kMaxSweepSteps = 10000;
// 1000 Hz = 60 000 rpm: ten times a rotation tester's 4000 rpm and far above
// any press roll (a 76 mm core at 30 m/s turns at 7500 rpm); a larger value
// is a unit slip (a plain number is in Hz, not rpm).
inline constexpr double kMaxRotationHz = 1000.0;
inline constexpr int kMaxRotationPoints = 1000;
// [response]: a dense reduced solve per speed is cheap, but 10 000 points is
// already a 1 mm/s step over a press's whole range.
inline constexpr int kMaxResponsePoints = 10000;
// [limits]: each diameter is a forced response and a Campbell sweep; 200
// diameters is already a step of a millimetre over a whole unwind.
inline constexpr int kMaxLimitsPoints = 200;
// Relative damping of cores and rest rolls: 0.005-0.02 (Ilomäki,
// I-1...4); 1 is critical damping, above which nothing oscillates.
inline constexpr PlausibleRange kPlausibleDampingRatio{1e-3, 0.2, 0.01, "cores and rest rolls: 0.005-0.02 (Ilomäki I-1...I-4; docs/reference/references.md)"};
// A material's loss factor (loss tangent tan delta, effects/damping.hpp):
// no published range for cores is built in, the value is the user's; the
// band catches slips (2 for 2 %): metals ~1e-4-1e-3, paper and polymers of
// order 1e-2-1e-1 (Nashif, Jones & Henderson, Vibration Damping, 1985, ch. 2).
// Above 1 the loss modulus exceeds the storage modulus: no roll part.
inline constexpr PlausibleRange kPlausibleLossFactor{1e-4, 0.2, 0.03, "loss factors of solids: ~1e-4 (steel) to ~0.1 (paper, polymers); the value is the user's"};
// The same as a logarithmic decrement, delta = 2 pi zeta (I-1).
inline constexpr PlausibleRange kPlausibleLogDecrement{6e-3, 1.3, 0.06, "2 pi times 0.001-0.2 (cores and rest rolls: 0.03-0.13)"};
// Straightness deviations of cores (ISO 11093-5) are tenths of a millimetre
// per metre; a bowed rest roll a few millimetres. Roundness deviations alike.
// Zero is a perfect roll (the default), so the ranges start at 0: they catch
// the slip that matters, a plain 0.5 read as 0.5 m.
inline constexpr PlausibleRange kPlausibleBow{0.0, 20e-3, 0.5e-3, "core straightness deviations are ~0.1-5 mm (ISO 11093-5)"};
inline constexpr PlausibleRange kPlausibleOvality{0.0, 10e-3, 0.3e-3, "core roundness deviations are ~0.1-2 mm (ISO 11093-5)"};
inline constexpr PlausibleRange kPlausibleEccentricity{0.0, 20e-3, 0.5e-3, "an eccentric rest roll: ~0.1-5 mm"};
// Unbalance: balancing grades put a 100 kg roll at ~1e-3-1e-2 kg m.
inline constexpr PlausibleRange kPlausibleUnbalance{0.0, 1.0, 2e-3, "rolls and cores: ~0.1-100 g m (balancing grades, ISO 21940)"};
// [web] (docs/theory/web.md): running tensions of printing and converting webs are
// ~100-1000 N/m (Roisum, The Mechanics of Web Handling, TAPPI 1998), a guide
// roller sits tens of centimetres to a few metres from the roll, papers and
// boards are 30 um to ~1 mm thick, and paper's in-plane moduli are a few GPa
// (MD 2-10 GPa: Niskanen, Paper Physics, 2nd ed., ch. 5).
inline constexpr PlausibleRange kPlausibleWebTension{5.0, 20e3, 300.0, "running web tensions are ~100-1000 N/m (Roisum 1998)"};
inline constexpr PlausibleRange kPlausibleWebSpan{0.02, 20.0, 1.0, "roll surface to the first guide roller: ~0.1-5 m"};
inline constexpr PlausibleRange kPlausibleWebThickness{10e-6, 3e-3, 80e-6, "papers and boards are ~30 um to ~1 mm thick"};
inline constexpr PlausibleRange kPlausibleWebModulus{0.2e9, 30e9, 5e9, "paper's in-plane moduli are ~2-10 GPa (Niskanen, Paper Physics)"};
// [traction] (docs/how-to/traction.md): Rice & Gans' rollers are 50 mm in radius,
// their grooves 36-43 um deep and 254 um apart (3937 per metre), their
// asperity engagement heights 0.4-26 um, their friction 0.13-0.55 (Tables 1-3
// of "A simple model to predict web-to-roller traction"); idler rollers of
// presses are ~25-300 mm in radius. Air's viscosity is 1.7-2.0e-5 Pa s from
// 0 to 100 C (1.81e-5 at room temperature, their Table 3).
inline constexpr PlausibleRange kPlausibleRollerRadius{5e-3, 1.0, 0.05, "web-handling rollers are ~25-300 mm in radius"};
inline constexpr PlausibleRange kPlausibleGrooveSize{5e-6, 10e-3, 200e-6,
                                              "roller grooves are tens of um to a few mm (Rice & Gans: 36-254 um)"};
inline constexpr PlausibleRange kPlausibleRoughness{0.0, 200e-6, 5e-6,
                                             "asperity engagement heights are ~0.4-26 um (Rice & Gans, Tables 1-2)"};
inline constexpr PlausibleRange kPlausibleFriction{0.05, 1.5, 0.3, "web on roller: 0.13-0.55 (Rice & Gans, Table 3)"};
inline constexpr PlausibleRange kPlausibleViscosity{1e-5, 3e-5, 1.81e-5,
                                             "air: 1.7-2.0e-5 Pa*s from 0 to 100 C (Rice & Gans, Table 3: 1.81e-5)"};
inline constexpr PlausibleRange kPlausibleWebDensity{100.0, 3000.0, 1000.0,
                                              "papers ~500-1200 kg/m^3, PET films 1358 kg/m^3 (Rice & Gans, Table 1)"};
inline constexpr PlausibleRange kPlausibleLimit{0.1e-3, 0.1, 5e-3, "the field's limit is +-5 mm at mid-span (Ilomäki, with I-5; docs/reference/references.md)"};

// Plausible ranges: one row per kind of value, each with its reason. They
// catch unit slips, which are factors of 1e3 to 1e9, so they are wide.
//
// Moduli: the softest solid in a roll, wound paper across its layers, is of
// order 10 MPa (Jorkama & von Hertzen, Fig. 4) and loose layers a few times softer; the
// stiffest engineering solids (tungsten carbide, diamond) are near 1 TPa.
inline constexpr std::string_view kModulusWhy =
    "from a loosely wound paper layer (~1 MPa; wound paper ~10 MPa, Jorkama & von Hertzen) to diamond (~1.1 TPa)";
inline constexpr double kMinPlausibleModulus = 0.1e6, kMaxPlausibleModulus = 1.2e12;  // Pa
// Typical moduli, the aim of a suggestion: paperboard in its plane (E_theta,
// E_z, G_thetaz), across it (E_r; G_rtheta, G_rz), and isotropic E (steel and
// aluminium tubes, steel chucks): docs/reference/material-sources.md, the materials library.
inline constexpr double kTypicalInPlane = 5e9, kTypicalAcross = 30e6, kTypicalShearAcross = 100e6;
inline constexpr double kTypicalShearInPlane = 2e9, kTypicalIsotropic = 70e9;  // Pa
// Density: the lightest foams (~10 kg/m^3) to the densest metals (osmium 22 600).
inline constexpr PlausibleRange kPlausibleDensity{10.0, 25e3, 1000.0,
                                           "from foams (~10 kg/m^3) to the densest metals (osmium, 22 600 kg/m^3)"};
// Cores: 1 inch (25 mm) to 600 mm inside (ISO 11093 sizes; docs/reference/references.md),
// rolls up to ~4 m across; walls from under a millimetre; a test ring cut from
// a core is a few millimetres long, the widest machines ~10 m.
inline constexpr PlausibleRange kPlausibleDiameter{5e-3, 4.0, 0.1, "cores are 25-600 mm inside, rolls up to ~4 m across"};
inline constexpr PlausibleRange kPlausibleWall{0.3e-3, 1.0, 0.015, "core walls from under a millimetre (film cores) to ~100 mm"};
inline constexpr PlausibleRange kPlausibleCoreLength{1e-3, 20.0, 1.5,
                                              "from a test ring cut from a core (a few mm) to the widest machines (~10 m)"};
inline constexpr PlausibleRange kPlausibleRestPaper{50e-6, 2.0, 0.01, "from one sheet of paper (~0.1 mm) to a full roll (~1.5 m)"};

}  // namespace coremodal::key_ranges
