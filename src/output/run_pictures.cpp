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
    Stopwatch clock;
    pictures.problem = run_python_plot("run-plot", dir, {"--modes", list});
    pictures.time_s = clock.seconds();
    if (!pictures.problem.empty()) return pictures;
    // python wrote them all or failed; look anyway, so that the report never
    // links a file that is not there.
    if (std::filesystem::exists(dir / "spectrum.png")) pictures.spectrum = "spectrum.png";
    for (int m : chosen)
        if (std::filesystem::exists(dir / mode_picture_file(m))) pictures.modes.push_back({m, mode_picture_file(m)});
    return pictures;
}

}  // namespace coremodal
