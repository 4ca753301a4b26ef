// The one picture of a results folder's report.md (campbell.png,
// response.png), drawn by `python3 -m coremodal SUBCOMMAND DIR` into the
// partial folder before report.md is written. A failed plot is a warning:
// the tables and report.md are complete without it.
#pragma once

#include "output/python_plots.hpp"

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace coremodal {

struct FolderPicture {
    std::vector<std::string> pngs;  // {png} when drawn
    std::string problem;            // why not ("switched off (--no-plots)", or the plot's failure)
};

inline FolderPicture draw_folder_picture(const std::string& subcommand, const std::filesystem::path& dir,
                                         const std::string& png, bool no_plots) {
    FolderPicture out;
    out.problem = no_plots ? "switched off (--no-plots)" : run_python_plot(subcommand, dir);
    if (out.problem.empty()) out.pngs = {png};
    else if (!no_plots)
        std::cerr << "coremodal: warning: plots not drawn: " << out.problem
                  << "; the tables and report.md are complete (draw them later with python3 -m coremodal " << subcommand
                  << " DIR)" << std::endl;
    return out;
}

}  // namespace coremodal
