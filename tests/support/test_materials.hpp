// Materials shared by unit tests.
#pragma once

#include "material/material.hpp"

namespace coremodal::testing {

// A paperboard-like set: radial modulus two orders below the in-plane ones,
// transverse shear soft, nu_zr = 0.002 * 6.5e9 / 33e6 = 0.39 (docs/reference/material-sources.md).
inline OrthotropicMaterial paperboard() {
    OrthotropicMaterial m;
    m.name = "paperboard";
    m.E_r = 33e6;
    m.E_theta = 4e9;
    m.E_z = 6.5e9;
    m.G_rtheta = m.G_rz = 130e6;
    m.G_thetaz = 1.8e9;
    m.nu_rtheta = m.nu_rz = 0.002;
    m.nu_thetaz = 0.3;
    m.density = 700;
    return m;
}

}  // namespace coremodal::testing
