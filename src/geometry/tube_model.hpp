// Builds the gmsh model of a tube-like scene: structured cross-sections (the
// core wall and rest paper as annuli, chuck bodies and shafts as O-grid
// discs) extruded along z segment by segment in explicitly graded layers,
// recombined into quadratic hexahedra. Every part shares the layers and the
// count around, so chuck nodes face core nodes (docs/theory/chucks.md).
// Physical groups (the names the rest of coremodal uses; a user mesh must
// carry the first ones, see docs/reference/case-scene.md):
//   volumes  "core", "rest_paper", "chuck_left", "chuck_right"
//   surfaces "core_inner", "core_outer", "rest_paper_outer", "clamp_<name>",
//            "interface_<chuck>_core", "interface_<chuck>_chuck", "bearing_<chuck>"
#pragma once

#include "geometry/tube_section.hpp"
#include "scene/scene.hpp"

namespace coremodal {

// Requires an initialised gmsh (GmshSession); leaves the meshed model current.
void build_tube_model(const TubeSection& section, const std::vector<ClampSpec>& clamps,
                      const std::string& element);

}  // namespace coremodal
