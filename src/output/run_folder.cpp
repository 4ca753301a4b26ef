#include "output/run_folder.hpp"

#include "output/beam_shapes.hpp"
#include "output/modes_h5.hpp"
#include "output/run_markdown.hpp"
#include "output/side_by_side.hpp"
#include "output/summary.hpp"
#include "output/text_file.hpp"
#include "output/xdmf.hpp"

#include <iostream>

namespace coremodal {

void write_run_folder(const RunReport& report, const std::filesystem::path& dir, bool force,
                      const std::function<RunPictures(ResultsFolder&)>& shapes) {
    ResultsFolder folder(dir, force);
    write_summary_json(folder.file("summary.json"), report);
    write_modes_csv(folder.file("modes.csv"), report);
    if (!report.rigid_comparison.empty())
        write_text_file(folder.file("rigid_vs_elastic.csv"), side_by_side_csv(report.rigid_comparison));
    const RunPictures pictures = shapes(folder);
    write_text_file(folder.file("report.md"), run_report_markdown(report, pictures));
    folder.commit();
}

RunPictures write_mesh_shapes(ResultsFolder& folder, const RunReport& report, const Mesh& mesh, bool plots) {
    write_modes_h5(folder.file("modes.h5"), mesh, report.modes.modes, report.scene.name, scene_json(report.scene),
                   "coremodal " COREMODAL_VERSION);
    write_modes_xdmf(folder.file("modes.xdmf"), "modes.h5", mesh, report.modes.modes);
    const RunPictures pictures = draw_run_pictures(folder.dir(), report.modes.modes, plots);
    if (plots && !pictures.problem.empty())
        std::cerr << "coremodal: warning: no pictures in report.md: " << pictures.problem << std::endl;
    return pictures;
}

RunPictures write_level_shapes(ResultsFolder& folder, const RunReport& report, const LevelShapes& shapes, bool plots) {
    if (shapes.mesh) return write_mesh_shapes(folder, report, *shapes.mesh, plots);
    write_beam_shapes_csv(folder.file("beam_shapes.csv"), *shapes.beam);
    RunPictures none;
    none.problem = "the beam model level has no mesh to draw (its mode shapes are in beam_shapes.csv)";
    return none;
}

}  // namespace coremodal
