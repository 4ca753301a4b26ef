// Builds the gmsh model of a tube-like scene: the r–z section revolved about
// the z axis in four quarter turns (gmsh's built-in kernel revolves by less
// than pi), seams merged, structured and recombined into quadratic hexahedra.
// Physical groups (the names the rest of coremodal uses, and that a user mesh
// must carry, see docs/case-files.md):
//   volumes  "core", "rest_paper"
//   surfaces "core_inner", "core_outer", "rest_paper_outer", "clamp_<name>"
#pragma once

#include "geometry/tube_section.hpp"
#include "scene/scene.hpp"

namespace coremodal {

// Requires an initialised gmsh (GmshSession); leaves the meshed model current.
void build_tube_model(const TubeSection& section, const std::vector<ClampSpec>& clamps,
                      const std::string& element);

}  // namespace coremodal
