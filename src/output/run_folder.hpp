// The results folder of a run, complete or not at all (ResultsFolder):
// summary.json, modes.csv, rigid_vs_elastic.csv (when compared), the model
// level's mode shapes and report.md with the pictures drawn from them.
#pragma once

#include "mesh/mesh.hpp"
#include "output/results_folder.hpp"
#include "output/run_pictures.hpp"
#include "results/level_shapes.hpp"
#include "results/run_report.hpp"

#include <filesystem>
#include <functional>

namespace coremodal {

// Writes the folder; `shapes` writes the level's shape files into it and
// returns the pictures for report.md (which is written last).
void write_run_folder(const RunReport& report, const std::filesystem::path& dir, bool force,
                      const std::function<RunPictures(ResultsFolder&)>& shapes);

// The shapes of a level with a mesh: modes.h5 and modes.xdmf on `mesh`,
// then the pictures, which read modes.h5 (none when `plots` is false; the
// run stays complete without them, and report.md says why).
RunPictures write_mesh_shapes(ResultsFolder& folder, const RunReport& report, const Mesh& mesh, bool plots);

// The shapes of any level (ModelLevel::shapes): on its mesh as above, or the
// beam network's beam_shapes.csv, which has no pictures (report.md says why).
RunPictures write_level_shapes(ResultsFolder& folder, const RunReport& report, const LevelShapes& shapes, bool plots);

}  // namespace coremodal
