// The a-priori mesh rule (issue 33, 12): the counts of a generated mesh
// chosen from the wanted band, before any solve. From the band's top it
// estimates the highest circumferential wave number n and the most axial
// half-waves h of a mode below it (thin-ring and beam formulas), then asks
// for as many elements around and along as keep the frequency error of
// those modes below the level's target, by error laws measured on this
// code's own elements (docs/validation/accuracy-by-level.md, "The mesh from the band";
// bench/mesh_rule_errors.py measures them):
//
//   around (the solid's hex20 ring, against the harmonic level, exact around):
//     e ~ kAroundFit (R/t)^1.585 n^1.285 N^-3.738, fitted over 40 points at
//     c >= 1.4 (R/t 3 to 25, n 2 to 6, N 16 to 64); every point lies within
//     0.81 to 1.54 times the fit, so the rule asks for kAroundSafety x the fit
//   along (the section's quad8/hex20 along z, at the harmonic level):
//     e <= kAlongFit (h / N_along)^3.7, the envelope of the bending, torsion
//     and axial modes of a free 76 x 15 mm tube (h = axial half-waves)
//   through the wall: 2 elements keep every measured mode within 0.2 %
//     (1 element: up to 0.8 %), so no level needs more than it has.
#pragma once

#include "scene/mesh_levels.hpp"

#include <optional>
#include <string>

namespace coremodal {

struct Scene;

// The relative frequency error a level's mesh aims at for the band's modes:
// default 1 % (the accuracy-vs-cost study's choice, mesh_levels.hpp), coarse
// 3 % (its measured ovalling error, a quick look), fine 0.3 %, very_fine 0.1 %.
double level_target_error(const MeshLevel& level);

// An explicit [mesh] count whose expected error is above this is warned
// about: the coarse level's 3 % times the around fit's spread (1.55), so
// that only a mesh beyond a quick look by every reading of the fit is. The
// band's n is an estimate that errs high, so a lower bar would warn about
// modes a scene may not have; the run's a-posteriori check (2 %,
// models/solid/mesh_resolution.hpp) sees the modes it has.
inline constexpr double kExplicitMeshWarnError = 0.05;

// What the band holds, estimated from the scene's dimensions and materials.
struct BandWaves {
    double top_hz = 0;           // [analysis] band's upper edge, or the estimated frequency of the last wanted mode
    bool top_estimated = false;  // true for a count of modes ([analysis] modes)
    int n_max = 1;               // highest ring wave number with a mode below top_hz (1: no ring mode)
    double n_max_hz = 0;         // its thin-ring frequency
    double half_waves = 1;       // most axial half-waves of a bending mode below top_hz (at least 1)
};
BandWaves band_waves(const Scene& scene);

// Expected relative frequency errors of the fitted laws above.
double expected_around_error(double slenderness, int n, int n_around);  // slenderness R / t
double expected_along_error(double half_waves, int n_along);

// The counts the band needs at a target error.
struct MeshRule {
    double target = 0;
    BandWaves band;
    double slenderness = 0;  // R / t of the slenderest layer (core or rest paper)
    int around = 0;          // elements around (a multiple of 4, at most kMaxLevelElementsAround; 0: no ring mode)
    int along = 0;           // elements along the core (at least kMinElementsAlong)
};
MeshRule mesh_rule(const Scene& scene, double target);

// The rule in one line for the run's output and `coremodal check`: the
// band, n and h, the counts it asks for and the expected errors of the
// scene's own counts, e.g. "mesh from the band (docs/validation/accuracy-by-level.md):
// top 700 Hz ([analysis] band), highest n = 6 (thin ring 651 Hz), 1 axial
// half-wave; for 1 % (level default): 68 around (expected 0.63 %), 8 along
// (expected 0.0 %)". Empty for a mesh file.
std::optional<std::string> mesh_rule_text(const Scene& scene);

// A warning when the scene's explicit (custom) counts are coarser than the
// band needs: their expected error above kExplicitMeshWarnError. Around
// only where it matters (`around_matters`: the solid level; at the harmonic
// levels it only draws the modes). The model levels give it when they run.
std::optional<std::string> explicit_mesh_warning(const Scene& scene, bool around_matters);

}  // namespace coremodal
