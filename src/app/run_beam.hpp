// The run pipeline for model = "beam": the scene as a Timoshenko beam network
// (beam/beam_model.hpp), reported like a solid run (console table,
// summary.json, modes.csv) plus the nodal shapes of the line model
// (beam_shapes.csv). No mesh, no PETSc solve, no modes.h5.
#pragma once

#include "app/run_case.hpp"
#include "beam/beam_model.hpp"

namespace coremodal {

// A beam mode as the writers know a mode (index from 1); shape: the
// translations of the network's nodes.
Mode report_mode(const BeamMode& mode, int index);

RunReport run_beam_scene(Scene scene, const RunOptions& options);

}  // namespace coremodal
