#include "output/run_pictures.hpp"

#include "common/stopwatch.hpp"
#include "output/python_plots.hpp"

#include <cstdio>
#include <set>

namespace coremodal {

std::vector<int> modes_to_picture(const std::vector<Mode>& modes, int max) {
    std::vector<int> chosen;
    std::set<std::string> types;
    for (const Mode& m : modes) {
        if (static_cast<int>(chosen.size()) >= max) break;
        if (m.label.type == "rigid" || !types.insert(m.label.type).second) continue;
        chosen.push_back(m.index);
    }
    return chosen;
}

std::string mode_picture_file(int mode) {
    char name[32];
    std::snprintf(name, sizeof name, "mode_%02d.png", mode);
    return name;
}

int mode_to_animate(const std::vector<Mode>& modes) {
    for (const Mode& m : modes)
        if (m.label.type == "bending") return m.index;
    for (const Mode& m : modes)
        if (m.label.type != "rigid") return m.index;
    return 0;
}

std::string frame_strip_file(int mode) {
    char name[40];
    std::snprintf(name, sizeof name, "mode_%02d_frames.png", mode);
    return name;
}

std::string animation_file(int mode) {
    char name[40];
    std::snprintf(name, sizeof name, "mode_%02d.gif", mode);
    return name;
}

RunPictures draw_run_pictures(const std::filesystem::path& dir, const std::vector<Mode>& modes, bool enabled) {
    RunPictures pictures;
    if (!enabled) {
        pictures.problem = "switched off (--no-plots)";
        return pictures;
    }
    const std::vector<int> chosen = modes_to_picture(modes);
    std::string list;
    for (int m : chosen) {
        if (!list.empty()) list += ',';
        list += std::to_string(m);
    }
    std::vector<std::string> args = {"--modes", list};
    const int animated = mode_to_animate(modes);
    if (animated > 0) args.insert(args.end(), {"--frames", std::to_string(animated)});
    Stopwatch clock;
    pictures.problem = run_python_plot("run-plot", dir, args);
    pictures.time_s = clock.seconds();
    if (!pictures.problem.empty()) return pictures;
    // python wrote them all or failed; look anyway, so that the report never
    // links a file that is not there.
    if (std::filesystem::exists(dir / "spectrum.png")) pictures.spectrum = "spectrum.png";
    for (int m : chosen)
        if (std::filesystem::exists(dir / mode_picture_file(m))) pictures.modes.push_back({m, mode_picture_file(m)});
    if (animated > 0 && std::filesystem::exists(dir / frame_strip_file(animated))) {
        pictures.frames_mode = animated;
        pictures.frames = frame_strip_file(animated);
        if (std::filesystem::exists(dir / animation_file(animated))) pictures.animation = animation_file(animated);
    }
    return pictures;
}

}  // namespace coremodal
