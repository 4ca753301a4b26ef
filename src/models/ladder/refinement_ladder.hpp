// The refinement ladders of `coremodal converge`: which meshes a model level
// runs, and what they cost, without running them.
//
// The solid's (and the harmonic's) ladder is uniform h-refinement by integer
// multiples: level k has k times the elements of a unit mesh in every
// direction (through the wall, through the rest paper, around, and in every
// axial segment), so the element size is exactly h = H/k everywhere, also in
// the graded segments next to clamp edges. A fixed ratio between levels is
// impossible with integer counts this small (one to four elements through a
// wall); exact proportional refinement with a known h matters more for
// Richardson than a constant ratio, and the extrapolation
// (numerics/richardson.hpp) takes any three h.
#pragma once

#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace coremodal {

// Element counts of the unit mesh (level k = 1). A "custom" unit comes from
// the command line (--unit W/P/A/Z).
struct UnitMesh {
    int n_wall = 1;        // through the core wall
    int n_rest_paper = 1;  // through the rest paper (ignored without rest paper)
    int n_around = 8;      // around; a multiple of 8 keeps the n = 2 pairs degenerate at every k
    int n_along = 0;       // along the whole core (distributed over the axial segments)
};

// The unit's elements around: 8, the fewest that represent an n = 2 ovalling
// wave and whose multiples keep the mesh symmetric under a 45-degree turn (a
// multiple of 4 only would split each ovalling pair by a mesh artefact).
inline constexpr int kUnitElementsAround = 8;

// The default unit of a scene: one element through the wall and one through
// the rest paper, 8 around, and along as many as keep the axial/circumferential
// element aspect of the scene's own mesh (at least kMinElementsAlong).
UnitMesh default_unit(const Scene& scene);

// Parses "W/P/A/Z" (e.g. "1/1/8/21"); throws InputError naming `option`.
UnitMesh parse_unit(const std::string& text, const std::string& option);

struct MeshStep {
    int k = 1;         // multiple of the unit mesh
    double h = 1;      // relative element size, 1/k
    MeshSpec mesh;     // the counts of this level (along: per axial segment)
    std::string counts;  // "3/3/24/63": wall/paper/around/along ("-" for no rest paper)
    std::string label;   // "k=3 3/3/24/63"
};

// "3/3/24/63": a mesh's elements through the wall / the rest paper ("-"
// without rest paper) / around / along.
std::string mesh_counts_text(const MeshSpec& mesh, bool rest_paper);

// DOFs of a generated tube mesh with these counts, before clamped nodes are
// eliminated (an upper bound within a few per cent): hex20 has corner nodes
// and mid-edge nodes, hex27 every node of the doubled grid.
long estimate_dofs(const MeshSpec& mesh, bool rest_paper);
// The same for the scene meshed with `mesh`: its axial segments as the mesher
// cuts them, and its chuck bodies and shafts (which can double a chuck
// scene's DOFs), counted without meshing.
long estimate_dofs(const Scene& scene, const MeshSpec& mesh);

// Fewest elements along the whole core in a unit mesh (level k = 1) that
// fit_unit_to_budget goes down to. Every axial segment keeps at least two
// elements whatever this number (the mesher's floor), so it bounds only the
// free spans; the finest level has k times as many.
inline constexpr int kMinUnitElementsAlong = 4;

// The cost bound of a study: the unit's elements along are lowered (to no
// fewer than kMinUnitElementsAlong) until the finest level's estimated DOFs are
// within max_dofs. Along is the direction to give up: the free span is graded
// towards the clamp edges and holds smooth waves, while the singular clamp
// edges keep their resolution through the per-segment minimum. Returns the
// unit used; `note` says what was changed ("" if nothing). max_dofs <= 0: no bound.
UnitMesh fit_unit_to_budget(const Scene& scene, UnitMesh unit, int first, int levels, long max_dofs,
                            std::string& note);

// Levels k = first, first+1, ..., first+levels-1 of the unit mesh on the
// scene's section: each axial segment gets exactly k times its unit count.
// Throws InputError for a user mesh file (nothing to refine) or an unusable unit.
std::vector<MeshStep> refinement_ladder(const Scene& scene, const UnitMesh& unit, int first, int levels);

// The harmonic model level's ladder is the solid's (refinement_ladder, the
// same unit, so level k meshes the same r-z section as the solid's level k)
// with this many finer levels: a harmonic run costs about a hundredth of the
// solid's on the same section, and its DOFs (one 2D problem) are not bound by
// --max-dofs.
inline constexpr int kHarmonicExtraLevels = 2;

// The beam model level's ladder (beam_refinement_ladder): level k refines the
// unit beam mesh (kBeamUnitElements along the core, BeamModelOptions) k times,
// k = 1, 2, 4, 8, 16, so h = 1/k exactly in every gap between support edges
// and in the chuck shafts. The three-node Timoshenko element (quadratic
// interpolation) converges frequencies as h^4: with a unit of 4 elements the
// triples from k = 2 on are in the asymptotic range for f1, torsion and axial
// on cases 01, 03 and 07 (observed orders 3.98 to 4.00, docs/validation/accuracy-vs-cost.md),
// and the finest change (k = 8 to 16, ~1e-6 of f1) stays far above the
// solver's round-off (kSolverNoise).
inline constexpr int kBeamUnitElements = 4;
inline constexpr int kBeamLevels = 5;
// One beam evaluation takes about a millisecond: a level's time is the median
// of this many runs (the solid's --repeats is far too few to beat the noise),
// or of as many as fit in kBeamLevelBudget seconds (the finest chuck levels,
// ~9000 DOFs, take ~50 ms a run).
inline constexpr int kBeamRunsPerLevel = 200;
inline constexpr double kBeamLevelBudget = 1.0;

// Levels k = 1, 2, 4, ... (levels of them) of the unit beam mesh; step.mesh is
// unused, step.counts is "core elements/network elements".
std::vector<MeshStep> beam_refinement_ladder(const Scene& scene, int unit_elements, int levels);

}  // namespace coremodal
