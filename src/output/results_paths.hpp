// The small things the results-folder code (output/results_folder,
// results_marker, results_lock) shares: an output path cleaned and
// suffixed, paths in messages, this machine and command line, and the
// refusal every check throws.
#pragma once

#include <filesystem>
#include <string>

namespace coremodal::results_paths {

// The output path as given, without a trailing separator ("out/" is "out";
// a partial folder "out/.partial-1" would be inside it) or "." and "..".
std::filesystem::path clean(const std::filesystem::path& p);

// `p` with `suffix` appended to its last name ("out" + ".lock").
std::filesystem::path suffixed(const std::filesystem::path& p, const std::string& suffix);

// A path in a message: 'out/tiny'.
std::string quoted(const std::filesystem::path& p);

// The folder `p` is in ("." for a bare name).
std::filesystem::path parent_folder(const std::filesystem::path& p);

// Whether `p` exists, without following a symbolic link.
bool exists_here(const std::filesystem::path& p);

// `p` absolute, with symbolic links of its existing part resolved.
std::filesystem::path resolved(const std::filesystem::path& p);

// This machine's name, and this process's command line as /proc/self/cmdline holds it.
std::string host_name();
std::string command_line();

// Throws InputError "output folder '<output>' <why>: <what_to_do>".
[[noreturn]] void refuse(const std::filesystem::path& output, const std::string& why, const std::string& what_to_do);

}  // namespace coremodal::results_paths
