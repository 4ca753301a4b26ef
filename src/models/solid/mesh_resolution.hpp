// Does the solid's mesh resolve the modes it reports? An a-posteriori
// estimate for scenes that are bodies of revolution: the harmonic level
// solves the same r-z section exactly in theta, so a solid mode's frequency
// against the harmonic level's mode of the same label (type, n, m) is the
// error of the mesh around the circumference (docs/validation/accuracy-by-level.md,
// "Does the mesh resolve the band"). It does not see the error through the
// wall or along the core: both levels share the section's mesh.
#pragma once

#include "modes/mode_set.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// Above this the run warns: twice the 1 % the default level is chosen to
// keep f1 and the first ovalling mode within (scene/mesh_levels.hpp).
constexpr double kMeshWarnError = 0.02;
// Above this the run fails, naming the mesh level it needs: 20 % in
// frequency is 44 % in stiffness, beyond the spread of any input the model
// takes (paperboard moduli are known to 10-15 %, which moves f by 5-8 %);
// the mode is then the mesh's, not the roll's.
constexpr double kMeshGrossError = 0.20;
// The error around the circumference falls as (n_around)^-p: p = 4 in the
// limit (quadratic cells, eigenvalue error of order h^4); measured on the
// n = 2 ovalling mode 3.7 from 16 to 24 and 3.8 from 24 to 32 around on a
// 76 x 3 mm steel tube, 3.8 from 32 to 48 on a steel ring of 0.5 m radius
// and 20 mm wall (docs/validation/accuracy-by-level.md, "Thin walls"). The lower value
// keeps the level named for a fix on the safe side.
constexpr double kAroundConvergenceOrder = 3.5;

// The worst-resolved solid mode against the harmonic level.
struct MeshResolution {
    int compared = 0;  // solid modes with a harmonic counterpart
    int mode_index = 0;  // the worst one (1-based)
    std::string label;
    double solid_hz = 0, harmonic_hz = 0;
    double error() const { return compared ? solid_hz / harmonic_hz - 1 : 0.0; }
};

// Every elastic solid mode (not rigid, support or mixed) against the
// harmonic mode of the same label at or just below it (the highest such; the
// nearest when none lies below).
MeshResolution compare_with_harmonic(const std::vector<Mode>& solid, const std::vector<Mode>& harmonic);

// The first named mesh level whose count around (for this core) brings
// `r`'s error under kMeshWarnError by the (n_around)^-p law, or empty when
// none does.
std::optional<std::string> level_that_resolves(const MeshResolution& r, const Scene& scene);

// The warning for a run, or empty when the mesh resolves every compared
// mode within kMeshWarnError.
std::optional<std::string> mesh_resolution_text(const MeshResolution& r, const Scene& scene);

}  // namespace coremodal
