// The 3D solid model level (model = "solid"): the scene's section extruded
// into quadratic hexahedra (or the user's mesh), clamped nodes eliminated,
// bonded bore nodes tied to their chuck nodes, the chuck supports as
// coupling elements; one OperatorSet, solved with SLEPc, each mode named on
// the mesh itself.
#pragma once

#include "assembly/chuck_supports.hpp"
#include "assembly/dof_map.hpp"
#include "mesh/mesh.hpp"
#include "models/model_level.hpp"

#include <optional>

namespace coremodal {

class SolidLevel : public ModelLevel {
public:
    int steps() const override { return 7; }
    LevelModes solve(const Scene& scene, const Printer& say) override;
    LevelShapes shapes() const override;
    // models/solid/solid_response.cpp
    std::unique_ptr<LevelResponse> response(const Scene& scene, const BeamModelOptions& options) override;
    // models/solid/solid_spinning.cpp
    std::unique_ptr<SpinningModel> spinning(const Scene& scene, const SpinningOptions& options) override;
    // models/solid/solid_ladder.cpp
    std::optional<ModelLadder> converge_ladder(const Scene& scene, const LadderRequest& request,
                                               std::vector<std::string>& notes) override;

private:
    std::optional<Mesh> mesh_;  // after solve: where the shapes live
};

// Step 2 of a solid run: the mesh, generated from the scene's section (with
// the frame nodes of elastic bearings) or read from the user's file, its
// physical groups checked against the scene.
Mesh make_solid_mesh(const Scene& scene);

// Step 3: the DOF map (clamped nodes and shaft ends in rigid bearings
// eliminated; bonded core nodes take their chuck node's DOFs) and the model
// summary in `out.info`; a warning in `out.warnings` for each part nothing holds.
DofMap solid_dofs(const Scene& scene, const Mesh& mesh, const ChuckSupports& chucks, LevelModes& out);

}  // namespace coremodal
