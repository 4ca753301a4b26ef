// The r–z section of a tube-like scene: radial layers (core wall, rest paper)
// times axial segments whose ends fall on every clamp-zone edge, so that clamp
// zones are unions of whole element faces. The section is what gets revolved
// about the z axis into hexahedra; a later axisymmetric-harmonic level meshes
// the same section in 2D.
#pragma once

#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace coremodal {

struct RadialLayer {
    std::string part;  // physical volume name: "core", "rest_paper"
    double r_inner = 0, r_outer = 0;  // m
    int n_elements = 1;
};

// How a segment's elements are sized along z. Clamp edges are stress
// singularities in a shear-soft wall (DOMAIN.md section 6): segments of the
// free core next to them are graded towards them.
enum class AxialGrading { uniform, toward_start, toward_end, toward_both };

struct AxialSegment {
    double z_start = 0, z_end = 0;  // m
    int n_elements = 1;
    AxialGrading grading = AxialGrading::uniform;
};

struct TubeSection {
    std::vector<RadialLayer> layers;    // from the inside out, sharing radii
    std::vector<AxialSegment> segments; // from z = 0 to the core length
    int n_around = 32;                  // elements around, a multiple of 4
};

// Builds the section of the scene's core (and rest paper) with the mesh
// density of scene.mesh. Segments get elements in proportion to their length,
// at least kMinElementsPerSegment each, unless scene.mesh.along_per_segment
// gives every segment's count.
TubeSection make_tube_section(const Scene& scene);

}  // namespace coremodal
