// The chuck and stand effects (effects/support_effects.hpp) at the solid
// level: how the core is held by each chuck over its expanding elements (ties
// or a spring layer per bore face), and how the chuck is held by the stand (a
// rigid bearing eliminates the shaft end face; bearing springs are spread
// over it, optionally through a frame node carrying the frame mass). This
// file only translates those effects into the solid's nodes and faces;
// docs/theory/chucks.md gives the formulas. The paper web's span (effects/web.hpp),
// like a bearing a spring to the ground, joins them as couplings on the
// faces of the roll's outer surface that its line crosses.
#pragma once

#include "assembly/cell_loop.hpp"
#include "assembly/dof_map.hpp"
#include "assembly/one_sided_contact.hpp"
#include "mesh/mesh.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace coremodal {

struct ChuckSupports {
    std::vector<int> eliminated;           // nodes of rigid bearing faces
    std::vector<NodeTie> ties;             // bonded core nodes -> facing chuck nodes
    std::vector<CouplingElement> couplings;  // spring layers, bearing springs, frame masses, contact placeholders
    // Bore faces of one-sided contacts (chucks not expanded). Each also has a
    // coupling above with structural zeros, so that the assembled matrices
    // have room for the contact springs the static state closes.
    std::vector<ContactFace> contact_faces;
    std::vector<int> grounded;             // nodes on springs to the ground (elastic bearings, frames)
    double coupled_area_m2 = 0;            // bore area held by expanding elements (both chucks)
};

// Mesh groups it reads (made by build_tube_model): "interface_<chuck>_core",
// "interface_<chuck>_chuck", "bearing_<chuck>", and the node group
// "frame_<chuck>" (one node) when the bearing has a frame mass.
ChuckSupports chuck_supports(const Scene& scene, const Mesh& mesh);

// Appends one node per chuck whose bearing has a frame mass, at the bearing
// centre, in node group "frame_<chuck>". No cell uses it; springs and the
// lumped mass attach to it.
void add_frame_nodes(const Scene& scene, Mesh& mesh);

}  // namespace coremodal
