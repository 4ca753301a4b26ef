// The marker file of a results folder (kResultsMarker, output/results_folder.hpp):
// what makes a folder coremodal's, and, once the folder is complete, the list
// of what coremodal wrote into that very folder ("contents", then one "wrote
// <path>" line per file and folder). What a folder holds beyond that list (a
// user's notes.txt, another results folder nested in it) keeps it from being
// replaced. Used by output/results_folder.cpp.
#pragma once

#include "output/results_folder.hpp"  // kResultsMarker, is_results_folder, marker_host

#include <filesystem>
#include <string>
#include <vector>

namespace coremodal::results_marker {

// Writes the marker into `folder`; with `contents`, the list of what
// coremodal wrote. Closed and checked: a full disk must not leave a marker of
// 0 bytes behind (throws InputError).
void write_marker(const std::filesystem::path& folder, const std::vector<std::string>* contents = nullptr);

// What a folder holds, as paths relative to it ('/' separated), the marker
// left out: the list its marker gets.
std::vector<std::string> listing(const std::filesystem::path& folder);

// What in a results folder keeps it from being replaced, the first few for a
// message ("" if nothing): what its marker does not list, results folders
// nested in it.
std::string in_the_way(const std::filesystem::path& folder);

}  // namespace coremodal::results_marker
