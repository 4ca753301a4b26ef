// Results folders: written by coremodal only where it cannot destroy the
// user's data, and complete or not at all (docs/reference/results.md, "Where results
// go").
//
// The rule. Every folder coremodal writes carries a marker file,
// kResultsMarker (program version, command, machine). An existing output
// path is replaced only if it is a real folder with that marker (or an empty
// folder, which is simply removed); the folder it replaces is kept as
// "<path>.previous" (an older .previous is replaced only if it carries the
// marker too, or is empty), or removed with --force. Anything else is
// refused before any work, with the path and what to do: a plain file, a
// symbolic link, a folder without the marker, the working folder or one of
// its parents, the home folder or one of its parents, "/". The place must be
// writable (its parent exists as a folder or can be created there).
//
// What is coremodal's. The marker of a finished folder lists what coremodal
// wrote into that very folder ("wrote <path>" lines). A folder is replaced
// only if it holds nothing else: a user's notes.txt added later, or another
// results folder written inside it (results/02-... inside results/, which
// carries its own marker), keeps it from being rotated or removed; the
// refusal names what is in the way. A marker without the list (written by
// an earlier version) is trusted, except for results folders nested in it.
// The marker's writing and reading: output/results_marker.hpp.
//
// One writer. Every command takes a lock on its output before any work
// (flock on "<path>.lock" next to it, with the holder's pid, host, command
// and start time in it) and keeps it until the process ends; a second run
// into the same output is refused with who holds it. The kernel releases
// the lock when its process dies, so a killed run never blocks the next
// (output/results_lock.hpp).
//
// Complete or not at all. ResultsFolder writes into "<path>.partial-<pid>"
// and renames it into place in commit(); a run that fails or is interrupted
// (common/signals.hpp) removes its partial folder, and a partial folder of a
// process that no longer runs (killed with SIGKILL, a power cut) is swept by
// the next run that writes the same path.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The marker file inside every results folder coremodal writes.
inline constexpr const char* kResultsMarker = ".coremodal-results";

// Whether `folder` is a results folder coremodal wrote: a folder (not a
// symbolic link) with the marker inside.
bool is_results_folder(const std::filesystem::path& folder);

// The machine named in the marker of `folder`, if it has a marker.
std::optional<std::string> marker_host(const std::filesystem::path& folder);

// Where an output path's replaced results are kept without --force.
std::filesystem::path previous_path(const std::filesystem::path& output);

// A command's results folder: --output as given, else
// "results/<name><suffix>" ("results/rest-roll-campbell").
std::filesystem::path results_path(const std::string& output, const std::string& name, const std::string& suffix);

// The checks of the rule above, made by every command before any work
// (and again when the folder is written). Throws InputError naming the path,
// why it is refused and what to do. Changes nothing on disk.
void prepare_output(const std::filesystem::path& output, bool force);

// prepare_output, then the output's lock taken for the rest of the process
// (a second call for the same output is a check only). Throws InputError
// when another process holds the lock, naming it. Under MPI with more than
// one rank it is collective: rank 0 checks and locks (it is the one writer)
// and every rank throws the same refusal.
void claim_output(const std::filesystem::path& output, bool force);

// Removes "<output>.partial-<pid>" and "<output>.old-<pid>" folders that
// carry the marker, name this machine and whose process no longer runs;
// returns how many were removed.
int sweep_stale_partials(const std::filesystem::path& output);

// A folder written in place rather than renamed into place (`coremodal
// batch`: its cases appear in it one by one): claimed as claim_output
// does, an older result moved to .previous (or removed with force), then
// created with the marker, which lists `contents` (relative paths; "x/"
// stands for the folder x and all in it) as coremodal's. A marker that cannot
// be written (a full disk) leaves no folder and the older result in place.
void start_folder_in_place(const std::filesystem::path& output, bool force,
                           const std::vector<std::string>& contents = {});

class ResultsFolder {
public:
    // Checks `final_path` again (prepare_output), takes its lock unless this
    // process holds it (then releases it with the folder), sweeps stale
    // partial folders and creates this process's partial folder with the marker.
    ResultsFolder(std::filesystem::path final_path, bool force);
    ~ResultsFolder();
    ResultsFolder(const ResultsFolder&) = delete;
    ResultsFolder& operator=(const ResultsFolder&) = delete;

    // Path of a file inside the (partial) folder.
    std::string file(const std::string& name) const;
    // The partial folder (for writers that take a folder).
    const std::filesystem::path& dir() const { return partial_; }
    // Lists what the partial folder holds in its marker, then puts it in
    // place: an older result moves to .previous (or is removed with force).
    // Throws Interrupted after an interrupt.
    void commit();
    const std::filesystem::path& final_path() const { return final_; }

private:
    std::filesystem::path final_, partial_;
    bool force_ = false;
    bool committed_ = false;
    bool own_lock_ = false;  // taken here, not by claim_output
};

}  // namespace coremodal
