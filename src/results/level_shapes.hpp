// Where a model level's mode shapes live, handed to the writers for step 8 of
// a run (output/run_folder: modes.h5 + modes.xdmf on a mesh, or
// beam_shapes.csv for the beam network). A level returns it and writes
// nothing itself, so models/ stays below output/. Exactly one of the two is
// set; both point into the level, which outlives the writing.
#pragma once

namespace coremodal {

struct Mesh;
struct BeamModelResult;

struct LevelShapes {
    const Mesh* mesh = nullptr;             // the solid's mesh, the revolved section
    const BeamModelResult* beam = nullptr;  // the beam network's modes
};

}  // namespace coremodal
