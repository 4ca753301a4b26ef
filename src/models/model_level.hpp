// A model level: how a Scene becomes named modes (steps 2–6 of a run). The
// run (analyses/run) does the other steps once for every level: read the
// case, compare with beam theory, the chuck factor and the rigid-clamp
// variant, the console tables and the results folder.
//
// Each level builds its model of the scene, splits it into independent
// problems (the whole solid: one OperatorSet; the harmonic level: one
// OperatorSet per wave number n; the beam network: one dense problem per
// motion family), solves each with a verified, complete solver, and expands
// every eigenvector into a Mode on a display mesh (the solid's own mesh, the
// r–z section revolved, the beam network's nodes), where modes/ names it.
// Why solve() is one call and not problems() + expand(): docs/architecture.md.
#pragma once

#include "results/level_shapes.hpp"
#include "results/run_report.hpp"

#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The providers' types, declared only: each caller includes the one it
// uses (models/linearised.hpp, models/spinning_model.hpp,
// models/response/level_response.hpp), so that a change to one provider
// does not recompile every file that names a level.
struct BeamModelOptions;
struct LadderRequest;
struct Linearised;
class LevelResponse;
struct ModelLadder;
class SpinningModel;
struct SpinningOptions;

// Progress lines on standard output, when on.
struct Printer {
    bool on;
    void operator()(const std::string& line) const {
        if (on) std::cout << "  " << line << std::endl;
    }
};

// What steps 2–6 give, at any model level.
struct LevelModes {
    ModelInfo info;
    std::vector<Mode> modes;  // in frequency order, indexed from 1, named on rank 0
    Verification verification;
    Timing timing;  // mesh, assemble, factor_and_solve, classify
    // About this level's model of the scene (printed already, from rank 0).
    std::vector<std::string> warnings;
    // What the level assumed beyond the scene (e.g. how an elastic bearing
    // holds the shaft axially), for the run summary.
    std::vector<std::string> assumptions;
};

class ModelLevel {
public:
    virtual ~ModelLevel() = default;
    // How many numbered progress steps a run at this level has ("[k/N]").
    virtual int steps() const = 0;
    // Steps 2–6: build the model, solve every independent problem (verified,
    // proven complete), expand and name the modes. Collective over
    // PETSC_COMM_WORLD; InputError / SolveError with a message for the user.
    virtual LevelModes solve(const Scene& scene, const Printer& say) = 0;
    // Step 8 (rank 0): where the level's mode shapes live (the display mesh,
    // or the beam network), for output/run_folder to write them into the
    // results folder (modes.h5 + modes.xdmf, or beam_shapes.csv) and draw
    // the pictures of report.md from them.
    virtual LevelShapes shapes() const = 0;
    // A line after the console tables, or "".
    virtual std::string console_note() const { return ""; }
    // The scene's distinct modes and their eigenvalues' change with the
    // operators (models/linearised.hpp), for `sensitivity`. Levels without
    // it (level_traits(...).sensitivities) refuse with an InputError.
    virtual Linearised linearise(const Scene& scene);
    // The scene's forced response (models/response/level_response.hpp), for
    // `response`, `limits` and `study`; `options` of the beam network (the
    // beam level's). Levels without one (level_traits(...).spins) refuse
    // with an InputError. The scene outlives the model.
    virtual std::unique_ptr<LevelResponse> response(const Scene& scene, const BeamModelOptions& options);
    // The level's model of the spinning scene (models/spinning_model.hpp),
    // for `campbell`. Levels that cannot spin (level_traits(...).spins)
    // refuse with an InputError.
    virtual std::unique_ptr<SpinningModel> spinning(const Scene& scene, const SpinningOptions& options);
    // The level's refinement ladder for `converge` (models/ladder/model_ladder.hpp),
    // or none, with the reason in `notes`, for a scene the level cannot solve.
    // Levels without one (level_traits(...).converge_ladder) refuse with an
    // InputError. The scene outlives the ladder.
    virtual std::optional<ModelLadder> converge_ladder(const Scene& scene, const LadderRequest& request,
                                                       std::vector<std::string>& notes);
};

// A warning about the model of a scene: on stderr from rank 0, named after
// `source`, and kept for the summary.
void warn_about_model(const std::string& source, const std::string& warning, std::vector<std::string>& warnings);

}  // namespace coremodal
