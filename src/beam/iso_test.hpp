// The virtual ISO 11093-8 test (Ilomäki I-13 and I-14): what the
// standard's free-hanging test would report as the core's flexural modulus
// from the first bending frequency of a free–free run, beside the E_z put in.
// The standard reads a beam (Euler–Bernoulli times its shear and rotary
// inertia factor Q) into the frequency of a shear-soft orthotropic tube, so
// the two differ by what Q does not capture (docs/how-to/calibration.md, "The
// virtual ISO 11093-8 test").
#pragma once

#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

struct IsoFlexuralTest {
    double f_free_hz = 0;        // the run's first bending frequency
    double length_m = 0;         // sample length (the core's)
    double mass_per_length = 0;  // kg/m, rho_c A_c: what the lab weighs and divides by L
    double Q = 0;                // I-14
    double flexural_modulus_pa = 0;  // I-13: Ec as the standard reports it
    double E_z_pa = 0;               // the wall's axial modulus put in
    double difference = 0;           // flexural_modulus / E_z - 1
    // Where the sample is outside ISO 11093-8's conditions (length at least
    // 8 Di; wall at least 0.02 Di and not under 2 mm).
    std::vector<std::string> notes;
};

// For a free scene of a bare core (no rest paper, no supports) with a first
// bending frequency; nothing otherwise.
std::optional<IsoFlexuralTest> iso_flexural_test(const Scene& scene, double f1_hz);

}  // namespace coremodal
