// The axisymmetric-harmonic model level (model = "harmonic", docs/theory/harmonic.md):
// the scene's r–z section meshed in 2D, one independent problem (an
// OperatorSet) per circumferential wave number n, the modes merged in
// frequency order, each expanded onto the section turned into 3D and named
// there with the solid's tools.
#pragma once

#include "geometry/section_mesh.hpp"
#include "models/model_level.hpp"

#include <optional>

namespace coremodal {

class HarmonicLevel : public ModelLevel {
public:
    int steps() const override { return 7; }
    // require_axisymmetric (models/choose.hpp) first.
    LevelModes solve(const Scene& scene, const Printer& say) override;
    LevelShapes shapes() const override;
    // models/harmonic/harmonic_response.cpp
    std::unique_ptr<LevelResponse> response(const Scene& scene, const BeamModelOptions& options) override;
    Linearised linearise(const Scene& scene) override;  // models/harmonic/harmonic_linearised.cpp
    // models/harmonic/harmonic_spinning.cpp
    std::unique_ptr<SpinningModel> spinning(const Scene& scene, const SpinningOptions& options) override;
    // models/harmonic/harmonic_ladder.cpp
    std::optional<ModelLadder> converge_ladder(const Scene& scene, const LadderRequest& request,
                                               std::vector<std::string>& notes) override;
    // After solve: the revolved section the modes' shapes live on.
    const std::optional<RevolvedMesh>& revolved() const { return revolved_; }

private:
    std::vector<Mode> verified_modes(const Scene& scene);
    std::optional<RevolvedMesh> revolved_;  // after solve: where the shapes live
};

}  // namespace coremodal
