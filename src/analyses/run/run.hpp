// The main analysis: one case file in, one verified and named mode set out,
// in numbered steps that are the same for every model level (models/): 1
// read the case; 2–6 the level builds, solves and names (ModelLevel::solve);
// 7 beam theory, the chuck factor (a run of the derived free-span scene) and
// the rigid-clamp variant (a run of the derived clamped scene); 8 the console
// tables and the results folder, by the writer the caller gives (RunWriter).
#pragma once

#include "results/run_report.hpp"

#include <functional>
#include <optional>
#include <string>

namespace coremodal {

class ModelLevel;
struct RunOptions;

// Step 8, given by the caller: the console tables and the results folder
// (output/run_writer.hpp: write_run, what `coremodal run` passes), called
// with the finished report and its level, which holds the mode shapes. The
// run itself writes nothing, so analyses/ stays below output/.
using RunWriter = std::function<void(const RunReport& report, const ModelLevel& level, const RunOptions& options)>;

struct RunOptions {
    std::string case_file;
    std::optional<std::string> output_dir;  // default results/<case name>
    bool force = false;                     // an earlier result at output_dir is removed, not kept as .previous
    bool quiet = false;                     // no progress lines (tests)
    bool write_results = true;
    std::optional<std::string> mesh_level;  // overrides the case's [mesh] level
    std::optional<ModelChoice> model;       // overrides the case's model level (--model)
    // Scenes with chucks: also solve the free-free roll over the free span for
    // f2 and k (a second, smaller solve). Off where only f1 matters (sweeps of f1).
    bool chuck_factor_by_fe = true;
    // Scenes with chucks: also run the rigid-clamp variant and pair the modes
    // (console table, rigid_vs_elastic.csv, summary.json "rigid_comparison").
    bool compare_rigid = false;
    // report.md with pictures drawn by the python package (mode shapes,
    // spectrum); false: the report says they were switched off.
    bool plots = true;
    // Modes that fail their verification (modes/verification_check.hpp) are
    // written, marked as not verified, instead of ending the run non-zero.
    bool keep_going = false;
    // Step 8; empty: nothing printed or written (derived scenes, sweeps, tests).
    RunWriter write;
};

// Runs the whole pipeline; collective over PETSC_COMM_WORLD. Throws
// InputError / SolveError with a message for the user.
RunReport run_case(const RunOptions& options);

// The case reader's warnings (values that look like slips: Scene::warnings),
// once on stderr from rank 0, for a command that has just read a case file.
void print_scene_warnings(const Scene& scene);

// Steps 2 onwards for a scene already in memory (options.case_file unused),
// at the level models/choose.hpp picks (the report's scene names it).
RunReport run_scene(Scene scene, const RunOptions& options);
// The same with the caller's level (make_model_level of the scene), kept
// across a sequence of like scenes so that it may reuse what it learned
// (the coupled level its truncation N: models/coupled/coupled_level.hpp).
RunReport run_scene(Scene scene, const RunOptions& options, ModelLevel& level);

// Steps 2–7a of a scene derived from the case (the free span, the rigid
// clamps): its modes and its beam comparison, quietly, nothing written, no
// chuck factor or variant of its own.
RunReport analyse_derived_scene(Scene scene);

// Ilomäki's chuck factor of a scene with chucks whose first bending mode is
// at f1: f2 by the scene's own model level on the free-free roll over the free
// span (when by_model; a solid scene uses the coarse level there) and by
// Timoshenko's formula, and k = f1 / f2.
ChuckFactor chuck_factor(const Scene& scene, double f1, bool by_model);

// The scene's first bending mode in `modes` against Euler-Bernoulli and
// Timoshenko beam theory over beam_span (any model level).
BeamComparison compare_with_beam(const Scene& scene, const std::vector<Mode>& modes);

// Rigid-body motions of a free body in three dimensions.
constexpr int kFreeBodyRigidModes = 6;

// A free scene (generated model, band from 0 if any) must show exactly its
// six rigid-body modes as its lowest; SolveError otherwise: the body is too
// thin for double precision to tell them from its elastic modes.
void check_rigid_modes(const RunReport& report);

}  // namespace coremodal
