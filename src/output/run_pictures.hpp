// The pictures of a run's report.md: a few mode shapes, the spectrum and
// the first bending mode swinging (a strip of frames and a GIF), drawn by the
// python package (`python3 -m coremodal run-plot DIR --modes ... --frames N`)
// from the modes.h5 just written. A run without them is still complete.
#pragma once

#include "modes/mode_set.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal {

// At most this many mode pictures: each costs about 0.6 s of CPU time on a
// 300 k-DOF result (docs/reference/results.md), and six cover the families a reader
// looks for (bending, torsion, axial, ovalling, breathing, mixed).
constexpr int kMaxModePictures = 6;

struct ModePicture {
    int mode = 0;      // 1-based, as in the mode table
    std::string file;  // "mode_07.png", inside the results folder
};

struct RunPictures {
    std::vector<ModePicture> modes;
    std::string spectrum;  // "spectrum.png", or "" when not drawn
    int frames_mode = 0;     // the mode drawn swinging (0: none)
    std::string frames;      // "mode_01_frames.png": side views at 5 phases, or ""
    std::string animation;   // "mode_01.gif": the same animated (python's PIL), or ""
    std::string problem;   // why there are no pictures ("" when drawn)
    double time_s = 0;     // wall time of the python process
};

// The modes worth a picture: the lowest mode of each type other than rigid,
// in order of frequency, at most `max`. The partner of a degenerate pair
// (same type, n, m) is the same picture turned, so it is never chosen twice.
std::vector<int> modes_to_picture(const std::vector<Mode>& modes, int max = kMaxModePictures);

// "mode_07.png": the file name python's run-plot writes for mode 7.
std::string mode_picture_file(int mode);

// The mode shown swinging in the report: the lowest bending mode, else the
// lowest mode that is not rigid; 0 if there is none.
int mode_to_animate(const std::vector<Mode>& modes);

// "mode_01_frames.png" and "mode_01.gif": what run-plot --frames 1 writes.
std::string frame_strip_file(int mode);
std::string animation_file(int mode);

// Draws the pictures into `dir` (which holds modes.h5). With `enabled`
// false, or when python fails, returns no pictures and the reason.
RunPictures draw_run_pictures(const std::filesystem::path& dir, const std::vector<Mode>& modes, bool enabled);

}  // namespace coremodal
