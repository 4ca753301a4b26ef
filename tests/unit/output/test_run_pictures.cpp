// Which modes the report draws, and the frame strip of the moving mode in
// report.md.
#include "output/run_markdown.hpp"
#include "output/run_pictures.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace coremodal;

namespace {

std::vector<Mode> modes_of(const std::vector<std::string>& types) {
    std::vector<Mode> modes;
    for (size_t i = 0; i < types.size(); ++i) {
        Mode m;
        m.index = static_cast<int>(i) + 1;
        m.frequency_hz = 10.0 * (i + 1);
        m.label.type = types[i];
        modes.push_back(m);
    }
    return modes;
}

}  // namespace

TEST_CASE("The mode shown swinging is the lowest bending mode", "[output][pictures]") {
    CHECK(mode_to_animate(modes_of({"rigid", "rigid", "torsion", "bending", "bending"})) == 4);
    // No bending mode: the lowest elastic one; only rigid modes: none.
    CHECK(mode_to_animate(modes_of({"rigid", "ovalling", "axial"})) == 2);
    CHECK(mode_to_animate(modes_of({"rigid", "rigid"})) == 0);
    CHECK(mode_to_animate({}) == 0);
}

TEST_CASE("File names of the frame strip and the GIF match python's run-plot", "[output][pictures]") {
    // python/coremodal/frames.py: strip_file and animation_file.
    CHECK(frame_strip_file(1) == "mode_01_frames.png");
    CHECK(animation_file(12) == "mode_12.gif");
    CHECK(frame_strip_file(123) == "mode_123_frames.png");
}

TEST_CASE("report.md embeds the frame strip and links the GIF when they were drawn", "[output][pictures]") {
    RunReport report;
    RunPictures p;
    p.spectrum = "spectrum.png";
    CHECK(run_report_markdown(report, p).find("swinging") == std::string::npos);

    p.frames_mode = 3;
    p.frames = "mode_03_frames.png";
    std::string md = run_report_markdown(report, p);
    CHECK(md.find("Mode 3 swinging:\n\n![mode 3 swinging](mode_03_frames.png)") != std::string::npos);
    CHECK(md.find(".gif") == std::string::npos);

    p.animation = "mode_03.gif";
    md = run_report_markdown(report, p);
    CHECK(md.find("Mode 3 swinging ([animated](mode_03.gif)):\n\n![mode 3 swinging](mode_03_frames.png)") !=
          std::string::npos);
}
