// The axisymmetric-harmonic model level (model = "harmonic", docs/harmonic.md):
// the scene's r–z section meshed in 2D, one eigenproblem per circumferential
// wave number n, the modes merged in frequency order, shown on the section
// turned into 3D.
#pragma once

#include "app/run_case.hpp"

#include <optional>
#include <string>

namespace coremodal {

// Why the harmonic level cannot solve the scene (a user [mesh] file, a
// segmented expanding element: both break the symmetry about the axis), or
// nothing when it can.
std::optional<std::string> why_not_axisymmetric(const Scene& scene);

// An InputError naming the case file and why_not_axisymmetric's reason,
// for a scene the harmonic level cannot solve (`run` and `check` refuse it alike).
void require_axisymmetric(const Scene& scene);

// The harmonic run; require_axisymmetric first.
RunReport run_harmonic_scene(Scene scene, const RunOptions& options);

}  // namespace coremodal
