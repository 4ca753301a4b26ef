#include "beam/iso_test.hpp"

#include "beam/formulas.hpp"
#include "common/format.hpp"

#include <algorithm>

namespace coremodal {
namespace {

// ISO 11093-8's sample: length at least 8 inner diameters, wall at least
// 2 % of the inner diameter and not under 2 mm (ISO 11093-8).
constexpr double kMinLengthPerDi = 8, kMinWallPerDi = 0.02, kMinWall = 2e-3;

}  // namespace

std::optional<IsoFlexuralTest> iso_flexural_test(const Scene& scene, double f1_hz) {
    if (scene.supports.kind != SupportKind::free || scene.rest_paper || !(f1_hz > 0)) return std::nullopt;
    const double Di = scene.core.inner_diameter, Do = scene.core.outer_diameter, L = scene.core.length;
    IsoFlexuralTest t;
    t.f_free_hz = f1_hz;
    t.length_m = L;
    const double A = tube_area(Do, Di), I = tube_inertia(Do, Di);
    t.mass_per_length = scene.core.material.density * A;
    t.Q = iso_free_free_shear_factor(L, I, A);
    t.flexural_modulus_pa = iso_flexural_modulus(f1_hz, t.mass_per_length, L, I, A);
    t.E_z_pa = scene.core.material.E_z;
    t.difference = t.flexural_modulus_pa / t.E_z_pa - 1;
    if (L < kMinLengthPerDi * Di)
        t.notes.push_back("the sample (" + significant(L * 1e3) + " mm) is shorter than ISO 11093-8's 8 Di = " +
                          significant(kMinLengthPerDi * Di * 1e3) + " mm");
    const double wall = (Do - Di) / 2;
    if (wall < std::max(kMinWallPerDi * Di, kMinWall))
        t.notes.push_back("the wall (" + significant(wall * 1e3) + " mm) is thinner than ISO 11093-8's minimum " +
                          significant(std::max(kMinWallPerDi * Di, kMinWall) * 1e3) + " mm");
    return t;
}

}  // namespace coremodal
