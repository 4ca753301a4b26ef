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
};

// Chosen by the accuracy-vs-cost study (`coremodal converge`,
// docs/accuracy-vs-cost.md): "default" is the cheapest level that puts both
// f1 and the first ovalling mode within 1 % of the extrapolated frequency in
// all three example scenes (worst: f1 of the clamped case 02, 0.6 %; ovalling
// 0.2-0.4 %). "coarse" keeps f1 within about 1 % but not ovalling (2-3 %:
// two elements through the wall and 16 around are too stiff in ring bending).
// Change them only with a new run of that study.
inline constexpr std::array<MeshLevel, 4> kMeshLevels = {{
    {"coarse", 2, 1, 16, 4.0},
    {"default", 3, 2, 32, 3.0},
    {"fine", 4, 3, 48, 2.0},
    {"very_fine", 6, 4, 64, 1.5},
}};

// Fewest elements along the core whatever the aspect ratio: fewer cannot
// resolve the first bending modes of a free-free or clamped tube.
inline constexpr int kMinElementsAlong = 8;
// More elements along than this is a mistake in the input (a core length in mm
// given as metres), not a mesh anyone wants to solve.
inline constexpr int kMaxElementsAlong = 100000;

const MeshLevel* find_mesh_level(std::string_view name);

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
