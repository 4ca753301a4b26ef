// The r–z section of a tube-like scene: radial layers (core wall, rest paper)
// times axial segments whose ends fall on every clamp-zone and expanding-
// element edge and at chuck body ends, so that held zones are unions of whole
// element faces; plus the chucks' solid parts. tube_model.hpp extrudes it into
// hexahedra; section_mesh.hpp meshes it in 2D for the axisymmetric-harmonic level.
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
// singularities in a shear-soft wall (docs/validation/accuracy-vs-cost.md): segments of the
// free core next to them are graded towards them.
enum class AxialGrading { uniform, toward_start, toward_end, toward_both };

struct AxialSegment {
    double z_start = 0, z_end = 0;  // m
    int n_elements = 1;
    AxialGrading grading = AxialGrading::uniform;
};

// An elastic chuck's solid parts: a body of radius body_radius inside the
// core over [z_body_start, z_body_end] (global z), and a shaft of radius
// shaft_radius <= body_radius from the core end outwards to the bearing.
// Solid cylinders are meshed as an O-grid (a centre square and rings) whose
// nodes around match the core's, so that core and chuck nodes face each other.
struct ChuckBody {
    std::string name;  // "left", "right": parts "chuck_<name>"
    double body_radius = 0, shaft_radius = 0;  // m
    double z_body_start = 0, z_body_end = 0;   // m
    bool shaft_below = true;  // left chuck: the shaft runs from z_body_start to -shaft_length
    double shaft_length = 0;  // m
    int n_shaft = 2;          // elements along the shaft
    double z_bearing() const { return shaft_below ? z_body_start - shaft_length : z_body_end + shaft_length; }
};

struct TubeSection {
    std::vector<RadialLayer> layers;    // from the inside out, sharing radii
    std::vector<AxialSegment> segments; // from z = 0 to the core length
    int n_around = 32;                  // elements around, a multiple of 4
    std::vector<ChuckBody> chucks;      // empty unless the scene has elastic chucks
    // Axial ranges [z0, z1] (global) of the expanding elements, per chuck name.
    std::vector<std::pair<std::string, std::pair<double, double>>> interfaces;
};

// Element boundaries of a segment as fractions of its length (after the
// start, ending with 1), graded as seg.grading says: the layer heights of the
// solid's extrusion and the axial nodes of the harmonic section mesh.
std::vector<double> segment_layer_fractions(const AxialSegment& seg);

// Half-width of the O-grid's centre square (corner distance from the axis)
// as a share of the shaft radius: 0.5 keeps the ring elements and the
// square's elements of similar size and shape.
inline constexpr double kOGridCoreShare = 0.5;

// Elements across a ring of a chuck's O-grid between radii r0 < r1, with
// n_around elements around: one unless the ring is more than
// kChuckRingAspect times as wide radially as around at r1.
int chuck_ring_elements(double r0, double r1, int n_around);

// Nodes of the chucks' bodies and shafts in the hex20 mesh tube_model builds
// from the section, counted without meshing (converge's DOF budget).
long count_chuck_hex20_nodes(const TubeSection& section);

// Builds the section of the scene's core (and rest paper) with the mesh
// density of scene.mesh. Segments get elements in proportion to their length,
// at least kMinElementsPerSegment each, unless scene.mesh.along_per_segment
// gives every segment's count.
TubeSection make_tube_section(const Scene& scene);

}  // namespace coremodal
