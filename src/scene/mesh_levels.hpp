// Named mesh refinement levels for the generated core / rest roll mesh.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace coremodal {

struct MeshLevel {
    std::string_view name;
    int n_wall;           // elements through the core wall
    int n_rest_paper;     // elements through the rest paper
    int n_around;         // elements around the circumference (multiple of 4)
    double axial_aspect;  // axial element length / circumferential element length at the core Do
    // Elements around per 2 pi sqrt(R / t) of the core wall (R its mean
    // radius, t its thickness), at least: below it a thin wall locks in ring
    // bending (see kMeshLevels). n_around is the larger of the two counts.
    double around_per_slenderness;
};

// Chosen by the accuracy-vs-cost study (`coremodal converge`,
// docs/validation/accuracy-by-level.md): "default" is the cheapest level that puts both
// f1 and the first ovalling mode within 1 % of the extrapolated frequency in
// all three example scenes (worst: f1 of the clamped case 02, 0.6 %; ovalling
// 0.2-0.4 %). "coarse" keeps f1 within about 1 % but not ovalling (2-3 %:
// two elements through the wall and 16 around are too stiff in ring bending).
// Change them only with a new run of that study.
//
// Thin walls (issue 33): a curved quadratic cell whose arc length s is long
// against sqrt(R t) locks in inextensional ring bending (membrane locking:
// the locking parameter is s^2 / (R t); Stolarski and Belytschko, "Membrane
// locking and reduced integration for curved elements", J. Appl. Mech. 49,
// 1982). With s = 2 pi R / n_around, s^2 / (R t) = 1 / c^2 where c =
// n_around / (2 pi sqrt(R / t)). Measured on the n = 2 ovalling mode against
// the harmonic level (exact around; docs/validation/accuracy-by-level.md, "Thin walls"):
// a steel ring of 0.5 m radius and 20 mm wall at c = 0.51: +45 %, 0.76:
// +10.8 %, 1.02: +3.7 %, 1.53: +0.8 %; a 76 x 3 mm steel tube at c = 0.70:
// +15 %, 1.05: +3.4 %, 1.40: +1.1 %. The per-level c keeps every shipped
// case's count (76 x 15 mm: 2 pi sqrt(R / t) = 10.9; 150 x 15.8 mm: 14.4)
// and raises it for thin walls (a 76 mm core with a 0.5 mm wall: 84 at
// `default`).
inline constexpr std::array<MeshLevel, 4> kMeshLevels = {{
    {"coarse", 2, 1, 16, 4.0, 1.0},
    {"default", 3, 2, 32, 3.0, 1.5},
    {"fine", 4, 3, 48, 2.0, 2.0},
    {"very_fine", 6, 4, 64, 1.5, 2.5},
}};

// Fewest elements along the core whatever the aspect ratio: fewer cannot
// resolve the first bending modes of a free-free or clamped tube.
inline constexpr int kMinElementsAlong = 8;
// The most elements around a thin wall gets from its level (a film core of
// 0.1 mm on a 152 mm bore asks for 260 at `default`); beyond, the run's
// mesh check says how far its modes are off (models/solid/mesh_resolution.hpp).
// The mode classifier resolves angles down to 2 pi / 1024 (modes/classify.cpp).
inline constexpr int kMaxLevelElementsAround = 512;
// More elements along than this is a mistake in the input (a core length in mm
// given as metres), not a mesh anyone wants to solve.
inline constexpr int kMaxElementsAlong = 100000;

const MeshLevel* find_mesh_level(std::string_view name);

// Elements around at a level for a core of these diameters (m): the level's
// count, or more for a thin wall (around_per_slenderness), a multiple of 4.
int elements_around(const MeshLevel& level, double inner_diameter, double outer_diameter);

// n_along = max(kMinElementsAlong, ceil(length / (aspect * pi * outer_diameter / n_around))),
// lengths in m. Empty when the result would exceed kMaxElementsAlong.
std::optional<int> elements_along(double length, double outer_diameter, int n_around,
                                  double axial_aspect);

// Replaces the mesh counts of a generated mesh by those of a named level
// (the command line's --mesh LEVEL). Throws InputError naming the valid
// levels for an unknown name, or if the scene uses a user mesh file.
struct Scene;
void apply_mesh_level(Scene& scene, std::string_view level_name);

}  // namespace coremodal
