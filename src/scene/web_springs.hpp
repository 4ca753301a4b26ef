// The paper web's three springs per unit length of roll (docs/theory/web.md;
// effects/web.hpp puts them on each level's DOFs), the default of its shear
// modulus, and what a run echoes of them. Here, below effects/, because the
// case reader applies the default and echoes the springs as the scene's
// assumptions when it reads [web] (issue 34: the reader needs no effects/).
#pragma once

#include "scene/scene.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace coremodal {

// The default in-plane shear modulus: G = 0.387 sqrt(E_MD E_CD) (Baum,
// Brennan & Habeger, Tappi 64(8), 1981, for machine-made papers) with
// E_CD = E_MD / 2 (MD/CD stiffness ratios of 1.5-3: Niskanen, Paper
// Physics, 2nd ed., ch. 5): 0.274 E_MD.
constexpr const char* kWebShearRule =
    "shear_modulus = 0.387 sqrt(E_MD E_CD) with E_CD = E_MD / 2 (Baum et al. 1981; MD/CD ratio 2): 0.274 x modulus";
inline double default_web_shear_modulus(double modulus) { return 0.387 * std::sqrt(modulus * modulus / 2); }

struct WebSprings {
    double along, across, axial;  // k_d = E t / s, k_n = T / s, k_z = (G t + T) / s: N/m^2
};
WebSprings web_springs(const WebSpec& web);

// The run's assumptions: the three springs and what is left out.
std::vector<std::string> web_assumptions(const WebSpec& web);

}  // namespace coremodal
