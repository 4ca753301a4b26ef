// The beam model level (model = "beam", docs/theory/beam.md): the scene as a
// Timoshenko beam network (beam/beam_model.hpp), one dense problem per
// motion family (beam/network_modes.hpp), each mode a Mode on the network's
// nodes. No mesh, no PETSc solve; its shapes go to beam_shapes.csv.
#pragma once

#include "beam/beam_model.hpp"
#include "models/model_level.hpp"

#include <optional>

namespace coremodal {

// A beam mode as the writers know a mode (index from 1); shape: the
// translations of the network's nodes.
Mode report_mode(const BeamMode& mode, int index);

class BeamLevel : public ModelLevel {
public:
    int steps() const override { return 4; }
    LevelModes solve(const Scene& scene, const Printer& say) override;
    LevelShapes shapes() const override;
    // models/beam/beam_response.cpp
    std::unique_ptr<LevelResponse> response(const Scene& scene, const BeamModelOptions& options) override;
    Linearised linearise(const Scene& scene) override;  // models/beam/beam_linearised.cpp
    // models/beam/beam_spinning.cpp
    std::unique_ptr<SpinningModel> spinning(const Scene& scene, const SpinningOptions& options) override;
    // models/beam/beam_ladder.cpp
    std::optional<ModelLadder> converge_ladder(const Scene& scene, const LadderRequest& request,
                                               std::vector<std::string>& notes) override;
    // The model's timing, in milliseconds.
    std::string console_note() const override;

private:
    std::optional<BeamModelResult> beam_;  // after solve
};

}  // namespace coremodal
