// `coremodal converge`: what accuracy costs in time. The parts of the study
// that need no solver, so that they can be unit-tested: the refinement ladder,
// tracking modes across its levels by label, Richardson extrapolation with an
// observed order, medians and power-law fits, and the report writers.
//
// The ladder is uniform h-refinement by integer multiples: level k has k times
// the elements of a unit mesh in every direction (through the wall, through
// the rest paper, around, and in every axial segment), so the element size is
// exactly h = H/k everywhere, also in the graded segments next to clamp edges.
// A fixed ratio between levels is impossible with integer counts this small
// (one to four elements through a wall); exact proportional refinement with a
// known h matters more for Richardson than a constant ratio, and the
// extrapolation below takes any three h.
#pragma once

#include "modes/mode_set.hpp"
#include "output/run_report.hpp"
#include "scene/scene.hpp"

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace coremodal {

// ---- the ladder -------------------------------------------------------------

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

// ---- one level's runs -------------------------------------------------------

// Where factor_and_solve goes, from PETSc's and SLEPc's event logs (seconds,
// rank 0): numeric and symbolic factorizations (the shift-and-invert
// Cholesky and the LDL^T of the inertia count), triangular solves, and the
// M-orthogonalization of the Krylov basis. The rest of factor_and_solve is
// the other Krylov-Schur work (M products, projected problem) and the
// residual and orthonormality checks. (Events are inclusive: the products of
// the shift-and-invert operator contain the solves, so they are not listed.)
struct SolverBreakdown {
    double factor_s = 0, solve_s = 0, orthogonalize_s = 0;
};

// What one run of one mesh level gives back (model-level independent).
struct LevelRun {
    long n_dofs = 0;
    Timing timing_s;
    SolverBreakdown solver_s;
    double cpu_s = 0;  // processor time of the run (user + system, this process, rank 0):
                       // on a shared machine less disturbed by other processes than wall time
    double peak_memory_mb = 0;
    std::vector<Mode> modes;  // frequency order; shapes not kept
    bool complete = true;     // the solver proved no mode missing
};

// A level after its repeated runs: medians of the timings, the largest peak.
struct LevelResult {
    MeshStep step;
    long n_dofs = 0;
    int runs = 0;
    Timing median_s;
    double median_cpu_s = 0;
    SolverBreakdown median_solver_s;
    double peak_memory_mb = 0;
    std::vector<Mode> modes;  // of the first run (every run solves the same mesh)
    bool complete = true;
    double max_repeat_spread = 0;  // largest relative frequency difference between runs
};

double median(std::vector<double> values);
LevelResult summarize_runs(const MeshStep& step, const std::vector<LevelRun>& runs);

// ---- tracking modes across levels --------------------------------------------

// A mode's identity across meshes: its label and which occurrence of that
// label it is (1 = the lowest). Degenerate partners (bending pairs, ovalling
// pairs) are one tracked mode.
struct ModeKey {
    std::string type;
    int n = 0, m = 0;
    int occurrence = 1;
    bool operator==(const ModeKey&) const = default;
    std::string text() const;  // "bending n=1 m=0" (+ " #2" for a second occurrence)
};

// Partners closer than this (relative frequency) with the same label are one
// mode. Exact pairs agree to ~1e-10; two distinct modes of one label are far
// apart. A pair split by a mesh that is not 45-degree symmetric (around a
// multiple of 4 only) differs by ~1e-5 to 1e-4, still one mode.
inline constexpr double kDegenerateTolerance = 1e-3;

struct DistinctMode {
    ModeKey key;
    double frequency_hz = 0;
    int index = 0;         // 1-based index of the first partner in the run
    int multiplicity = 1;  // 2 for a degenerate pair
};

// Distinct elastic modes of one run: rigid and mixed modes are left out
// (a mixed label cannot be matched across meshes).
std::vector<DistinctMode> distinct_modes(const std::vector<Mode>& modes);

// The roles the study reports on: the first bending mode f1, the first
// ovalling mode, the first torsion, axial and breathing modes.
inline const std::vector<std::pair<std::string, std::string>> kModeRoles = {
    {"f1", "bending"}, {"ovalling", "ovalling"}, {"torsion", "torsion"}, {"axial", "axial"},
    {"breathing", "breathing"}};

// Result of Richardson extrapolation f(h) = f0 + C h^p from three levels.
struct Richardson {
    bool extrapolated = false;  // false: f0 is the finest value, see note
    double order = 0;           // observed p (0 when not extrapolated)
    double f0 = 0;              // extrapolated value
    double error_estimate = 0;  // |f_finest - f0| (for oscillating sequences the largest change)
    bool asymptotic = false;    // order plausible, and consistent with the previous triple if there is one
    std::optional<double> previous_order;  // p from the triple one level coarser
    std::optional<double> previous_f0;     // f0 from that triple
    std::optional<double> f0_uncertainty;  // |f0 - previous_f0|: how well f0 itself is known
    std::string note;           // plain words for the report
};

// Plausible observed orders: quadratic elements give eigenvalue errors ~ h^4
// on smooth problems; stress singularities at clamp edges lower that towards 1
// or below (DOMAIN.md section 6). Outside this range the levels are not in
// the asymptotic range and the report says so.
inline constexpr double kMinPlausibleOrder = 0.5;
inline constexpr double kMaxPlausibleOrder = 8.0;
// Two triples agree on the order when they differ by less than this fraction.
inline constexpr double kOrderConsistency = 0.25;
// Changes below this relative size are the eigen solver's round-off (its
// tolerance is 1e-10 on eigenvalues): such a mode has converged.
inline constexpr double kSolverNoise = 1e-9;

// Three levels, coarse to fine (h1 > h2 > h3 > 0). Solves
// (f1 - f2)/(f2 - f3) = (h1^p - h2^p)/(h2^p - h3^p) for p by bisection
// (the right side grows monotonically with p), then f0 = f3 - C h3^p.
Richardson richardson_three(const double h[3], const double f[3]);

// Extrapolation from the three finest of n >= 3 levels, with the previous
// triple's order and f0 for the consistency check when n >= 4.
Richardson richardson(const std::vector<double>& h, const std::vector<double>& f);

struct TrackedMode {
    ModeKey key;
    std::string role;                               // "f1", "ovalling", ... or "" (tracked, no role)
    std::vector<std::optional<double>> frequency_hz;  // per level; empty when the label is missing
    std::optional<Richardson> richardson;           // when the three finest levels have it
    std::vector<std::optional<double>> relative_error;  // |f - f0| / f0 per level
};

// Modes tracked across levels: every label present at every level, plus the
// role modes (labels taken from the finest level) even if a coarser level
// lacks them. Sorted by the finest level's frequency.
std::vector<TrackedMode> track_modes(const std::vector<LevelResult>& levels);

// Least-squares slope of log(y) against log(x): y ~ x^slope. Needs >= 2
// points with positive values, else nullopt.
std::optional<double> power_law_exponent(const std::vector<double>& x, const std::vector<double>& y);

// ---- model levels -------------------------------------------------------------

// The beam model level's ladder (beam_refinement_ladder): level k refines the
// unit beam mesh (kBeamUnitElements along the core, BeamModelOptions) k times,
// k = 1, 2, 4, 8, 16, so h = 1/k exactly in every gap between support edges
// and in the chuck shafts. The three-node Timoshenko element (quadratic
// interpolation) converges frequencies as h^4: with a unit of 4 elements the
// triples from k = 2 on are in the asymptotic range for f1, torsion and axial
// on cases 01, 03 and 07 (observed orders 3.98 to 4.00, docs/accuracy-vs-cost.md),
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

// The harmonic model level's ladder is the solid's (refinement_ladder, the
// same unit, so level k meshes the same r-z section as the solid's level k)
// with this many finer levels: a harmonic run costs about a hundredth of the
// solid's on the same section, and its DOFs (one 2D problem) are not bound by
// --max-dofs.
inline constexpr int kHarmonicExtraLevels = 2;

// A model level's refinement ladder and how to run one of its levels once.
// The solid ladder is refinement_ladder(), the harmonic's the same with
// kHarmonicExtraLevels more, the beam's beam_refinement_ladder();
// app/converge_command.cpp builds them.
struct ModelLadder {
    std::string model;   // "solid", "beam", "harmonic"
    std::string note;    // how the ladder was built, for the report
    std::vector<MeshStep> steps;
    std::function<LevelRun(const MeshStep&)> run_once;  // collective over PETSC_COMM_WORLD
    int n_modes = 0;             // modes asked per run (the solid's is fixed by choose_mode_count)
    int runs_per_level = 0;      // 0: --repeats; the beam: kBeamRunsPerLevel
    double level_budget_s = 0;   // > 0: no further run once a level's runs took this long in all
    int refined_dimensions = 3;  // DOFs ~ k^this (3 for the solid, 2 for the harmonic, 1 for the beam)
    // Roles (kModeRoles) this model cannot have, and why (the beam: ovalling
    // and breathing, which deform the cross-section).
    std::vector<std::pair<std::string, std::string>> unseen_roles;
};

// ---- the study --------------------------------------------------------------

// All levels of one model level ("solid", "beam", "harmonic") and what they say.
struct ModelStudy {
    std::string model;
    std::string ladder_note;  // how the ladder was built, for the report
    std::vector<LevelResult> levels;
    std::vector<TrackedMode> modes;
    std::optional<double> time_exponent;    // total time ~ DOFs^e (levels after the coarsest)
    std::optional<double> memory_exponent;  // peak memory ~ DOFs^e
    int n_modes = 0;                        // modes asked per run
    int refined_dimensions = 3;             // DOFs ~ k^this, for predict_level_for
    std::vector<std::pair<std::string, std::string>> unseen_roles;  // ModelLadder::unseen_roles
};

// A model level's converged value of a role against the solid's: the model
// error, which no refinement of the simpler model removes (a beam never
// converges to the 3D answer). For the harmonic level, which is exact in
// theta on the solid's own r-z section, the difference is instead the solid's
// circumferential discretization error left in its extrapolated f0 (the
// solid's ladder refines around together with the section), plus both
// extrapolations' noise.
struct ModelError {
    std::string model, role;
    std::string id, solid_id;  // the tracked modes' labels
    double f0_hz = 0, solid_f0_hz = 0;
    double relative = 0;        // (f0 - solid f0) / solid f0
    double known_to = 0;        // both extrapolations' error estimates and f0 uncertainties, relative
};

// For every model level other than the solid and every role both have
// extrapolated (kModeRoles order).
std::vector<ModelError> model_errors(const std::vector<ModelStudy>& models);

// |f - f0 of the solid's mode of the same role| / that f0, per level of a
// tracked mode of another model level; empty when the solid has no such f0.
std::vector<std::optional<double>> error_against_solid(const TrackedMode& mode, const std::vector<ModelStudy>& models);

// A named mesh level (--check-levels) run once and compared with the study's
// extrapolated values: how good is "default"?
struct NamedLevelCheck {
    std::string name;
    std::string mesh;  // wall/paper/around/along
    LevelResult result;
};

struct ConvergeStudy {
    std::string case_name, source_file;
    int n_modes = 0;           // modes asked per solid run (ModelStudy::n_modes per model level)
    int repeats = 0;           // runs per level asked (levels slower than repeat_limit_s run once)
    double repeat_limit_s = 0;
    std::vector<ModelStudy> models;
    std::vector<NamedLevelCheck> checks;  // solid model only
    std::vector<std::string> notes;
    double total_time_s = 0;
    double ladder_time_s = 0;  // the ladders alone (total less the named-level checks)
    // The machine's 1-minute load average at the start and the end: timings
    // on a shared machine include waiting for other processes.
    double load_start = 0, load_end = 0;
    int n_cores = 0;
};

ModelStudy analyse_levels(std::string model, std::string ladder_note, std::vector<LevelResult> levels);

// The accuracy targets of the report: 1 %, 0.1 %, 0.01 %.
inline const std::vector<double> kAccuracyTargets = {1e-2, 1e-3, 1e-4};

// The cheapest level whose error, plus the uncertainty of f0, is within the
// target; nullopt if none is.
std::optional<std::size_t> first_level_within(const TrackedMode& mode, double target);

// ---- running it (app/converge_command.cpp: needs PETSc) ---------------------

// The finest level's default DOF bound: ~190 k DOFs solve in about 85 s on
// the 2-core reference machine (docs/performance.md), so that a four-level
// study of the 4.32 m rest roll fits in a few minutes.
inline constexpr long kDefaultMaxDofs = 200000;

struct ConvergeOptions {
    std::string case_file;
    std::optional<std::string> output_dir;  // default results/<case name>-converge
    bool force = false;                     // an earlier result there is removed, not kept as .previous
    int levels = 4;                         // k = first ... first + levels - 1
    int first = 1;
    std::optional<std::string> unit;        // "W/P/A/Z"; default: default_unit(scene)
    int repeats = 3;                        // runs per level; the median time is reported
    double repeat_limit_s = 30;             // a level whose first run takes longer runs once
    long max_dofs = kDefaultMaxDofs;        // bound on the finest level (fit_unit_to_budget); 0: none
    std::optional<int> n_modes;             // modes per run; default: the case's, raised
                                            // until the coarsest level shows an ovalling mode
    std::vector<std::string> check_levels;  // named mesh levels to compare with f0
    // Model levels to run: those of them the scene allows (the beam and the
    // harmonic level are skipped, with a note, for a scene they cannot solve).
    std::vector<std::string> models = {"solid", "beam", "harmonic"};
    bool quiet = false;
    bool write_results = true;
};

// Most modes asked per run while looking for the first ovalling mode.
inline constexpr int kMaxModesForOvalling = 64;

// Runs the study and writes the results folder; collective. Throws InputError
// for bad options or case files.
ConvergeStudy run_converge(const ConvergeOptions& options, std::ostream& progress);

// Where the ladder would have to go for a target it does not reach, from the
// observed order (error ~ (1/k)^p from the finest level), DOFs ~ k^d (d =
// ModelStudy::refined_dimensions: 3 for the solid, 1 for the beam) and the
// observed time exponent. Nothing when the mode is not asymptotic or when f0
// itself is not known to better than the target.
struct TargetPrediction {
    double k = 0;
    double n_dofs = 0;
    std::optional<double> time_s;
};
std::optional<TargetPrediction> predict_level_for(const ModelStudy& model, const TrackedMode& mode, double target);

// Writers: converge.csv (one row per model x level x tracked mode),
// converge.json (everything, for the plot), converge.md (the report; embeds
// error_vs_time.png when plot_note is empty, else prints the note).
std::string converge_csv(const ConvergeStudy& study);
std::string converge_json(const ConvergeStudy& study);
std::string converge_markdown(const ConvergeStudy& study, const std::string& plot_note);

}  // namespace coremodal
