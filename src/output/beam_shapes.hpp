// beam_shapes.csv: the beam level's mode shapes, one row per mode and node.
#pragma once

#include "beam/beam_model.hpp"

#include <string>

namespace coremodal {

// One row per mode and node: z and the six motions (M-normalised).
void write_beam_shapes_csv(const std::string& path, const BeamModelResult& beam);

}  // namespace coremodal
