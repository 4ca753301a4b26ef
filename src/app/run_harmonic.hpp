// The axisymmetric-harmonic model level (model = "harmonic", docs/harmonic.md):
// the scene's r–z section meshed in 2D, one eigenproblem per circumferential
// wave number n, the modes merged in frequency order, shown on the section
// turned into 3D.
#pragma once

#include "app/run_case.hpp"

namespace coremodal {

// Throws InputError (naming the case file and the reason) unless the harmonic
// level can solve the scene: no user [mesh] file, no segmented expanding
// element (both break the axial symmetry the harmonic level assumes).
void require_axisymmetric(const Scene& scene);

// Throws InputError (naming the case file) for a scene that is not
// axisymmetric: segmented expanding elements or a user mesh.
RunReport run_harmonic_scene(Scene scene, const RunOptions& options);

}  // namespace coremodal
