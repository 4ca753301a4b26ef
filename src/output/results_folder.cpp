#include "output/results_folder.hpp"

#include "output/report_html.hpp"

#include "common/error.hpp"
#include "common/signals.hpp"
#include "output/results_lock.hpp"
#include "output/results_marker.hpp"
#include "output/results_paths.hpp"

#include <mpi.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {
namespace fs = std::filesystem;
using namespace results_lock;
using namespace results_marker;
using namespace results_paths;

namespace {

// What may be replaced: a results folder coremodal wrote that holds nothing
// else, or an empty folder (nothing in it to lose; `mkdir out` before a run
// is common). An empty folder is removed with rmdir, which refuses if a file
// appeared.
bool replaceable(const fs::path& folder) {
    std::error_code ec;
    return (is_results_folder(folder) && in_the_way(folder).empty()) ||
           (fs::is_directory(fs::symlink_status(folder, ec)) && fs::is_empty(folder, ec) && !ec);
}

const std::string kChooseAnother = "choose another folder (a new one, or an earlier coremodal result)";

// What `target` is among the places never to replace, "" if none: "/", the
// working folder, the home folder and their parents.
std::string protected_place(const fs::path& target) {
    const fs::path t = resolved(target);
    if (t == t.root_path()) return "the root folder";
    const auto relation = [&](const fs::path& place, const std::string& name) -> std::string {
        for (fs::path p = resolved(place);; p = p.parent_path()) {
            if (p == t) return p == resolved(place) ? "the " + name : "a parent of the " + name;
            if (p == p.parent_path()) return "";
        }
    };
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    const std::string working = ec ? "" : relation(cwd, "working folder");
    if (!working.empty()) return working;
    const char* home = std::getenv("HOME");
    return home && *home ? relation(home, "home folder") : "";
}

// The output's parent folder exists, or can be created under its nearest
// existing ancestor, which must be a folder this process can write in: tried
// by creating and removing a folder there (access(2) says yes to root on a
// read-only file system).
void require_writable_place(const fs::path& output) {
    std::error_code ec;
    fs::path ancestor = fs::absolute(parent_folder(output), ec);
    while (!fs::exists(ancestor, ec) && ancestor.has_relative_path()) ancestor = ancestor.parent_path();
    if (!fs::is_directory(ancestor, ec))
        refuse(output, "cannot be created", quoted(ancestor) + " is a file, not a folder; " + kChooseAnother);
    const fs::path probe = suffixed(ancestor / ".coremodal-write-test-", std::to_string(::getpid()));
    if (::mkdir(probe.c_str(), 0700) != 0 && errno != EEXIST)
        refuse(output, "cannot be written",
               "no folder can be made in " + quoted(ancestor) + " (" + std::strerror(errno) +
                   "); choose a folder you can write to");
    ::rmdir(probe.c_str());
}

// The result at `output` moved out of the way before a new one takes its
// place: to .previous, or (force) aside to be removed once the new one is in.
struct Retired {
    fs::path moved_to;  // empty: there was no result
    bool remove = false;
};

Retired retire(const fs::path& output, bool force) {
    if (!exists_here(output)) return {};
    if (!is_results_folder(output)) {  // empty (prepare_output checked): nothing to keep
        fs::remove(output);
        return {};
    }
    if (force) {
        const fs::path aside = suffixed(output, ".old-" + std::to_string(::getpid()));
        fs::rename(output, aside);
        return {aside, true};
    }
    const fs::path previous = previous_path(output);
    if (exists_here(previous)) fs::remove_all(previous);  // ours or empty: prepare_output checked
    fs::rename(output, previous);
    return {previous, false};
}

std::optional<int> leftover_pid(const std::string& name, const std::string& stem) {
    for (const char* suffix : {".partial-", ".old-"}) {
        const std::string prefix = stem + suffix;
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string digits = name.substr(prefix.size());
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
        return std::stoi(digits);
    }
    return std::nullopt;
}

// Whether a process with this number runs. This process's own number on a
// leftover folder is an earlier process's (it has not made its own yet).
bool process_running(int pid) {
    if (pid == ::getpid()) return false;
    return ::kill(pid, 0) == 0 || errno == EPERM;
}


// Whether this process is the one that writes: rank 0, or the only process.
bool writing_rank() {
    int up = 0, down = 0;
    MPI_Initialized(&up);
    MPI_Finalized(&down);
    if (!up || down) return true;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank == 0;
}

int world_size() {
    int up = 0, down = 0;
    MPI_Initialized(&up);
    MPI_Finalized(&down);
    if (!up || down) return 1;
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
}

// Rank 0's `message` on every rank.
std::string from_rank_zero(std::string message) {
    int size = static_cast<int>(message.size());
    MPI_Bcast(&size, 1, MPI_INT, 0, MPI_COMM_WORLD);
    message.resize(static_cast<size_t>(size));
    MPI_Bcast(message.data(), size, MPI_CHAR, 0, MPI_COMM_WORLD);
    return message;
}

}  // namespace

fs::path previous_path(const fs::path& output) { return suffixed(clean(output), ".previous"); }

std::filesystem::path results_path(const std::string& output, const std::string& name, const std::string& suffix) {
    return output.empty() ? std::filesystem::path("results") / (name + suffix) : std::filesystem::path(output);
}

void prepare_output(const fs::path& given, bool force) {
    const fs::path output = clean(given);
    if (output.empty()) throw InputError("output folder is empty: give a folder name");
    const std::string place = protected_place(output);
    if (!place.empty())
        refuse(output, "is " + place, "coremodal never replaces it; " + kChooseAnother);
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(output, ec);
    if (fs::is_symlink(status))
        refuse(output, "is a symbolic link", "coremodal neither replaces links nor writes through them; " +
                                                 kChooseAnother + ", or remove the link yourself");
    if (fs::exists(status) && !fs::is_directory(status))
        refuse(output, "is a file, not a folder",
               "coremodal does not replace it; " + kChooseAnother + ", or remove the file yourself");
    if (fs::exists(status) && !replaceable(output)) {
        if (!is_results_folder(output))
            refuse(output, std::string("exists and was not written by coremodal (no ") + kResultsMarker + " file in it)",
                   "coremodal only replaces its own results; " + kChooseAnother + ", or move or remove it yourself");
        refuse(output, "holds what coremodal did not write into it: " + in_the_way(output),
               "coremodal never replaces a results folder that holds anything else (your files, or another "
               "results folder inside it); move those out yourself, or choose another folder");
    }
    const fs::path previous = previous_path(output);
    if (fs::exists(status) && !force && exists_here(previous) && !replaceable(previous)) {
        const std::string why = is_results_folder(previous)
                                    ? "which holds what coremodal did not write into it: " + in_the_way(previous)
                                    : "which is not a coremodal results folder";
        refuse(output, "would be kept as " + quoted(previous) + ", " + why,
               "move or remove " + quoted(previous) + " yourself, or give --force to replace " +
                   quoted(output) + " without keeping it");
    }
    require_writable_place(output);
}

void claim_output(const fs::path& given, bool force) {
    const fs::path output = clean(given);
    const auto claim = [&] {
        prepare_output(output, force);
        if (take_lock(output)) prepare_output(output, force);  // again: another run may just have finished
    };
    if (world_size() == 1) return claim();
    std::string refusal;
    if (writing_rank()) {
        try {
            claim();
        } catch (const InputError& e) {
            refusal = e.what();
        }
    }
    refusal = from_rank_zero(refusal);
    if (!refusal.empty()) throw InputError(refusal);
}

int sweep_stale_partials(const fs::path& given) {
    const fs::path output = clean(given);
    const std::string stem = output.filename().string();
    const std::string host = host_name();
    std::vector<fs::path> stale;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(parent_folder(output), ec)) {
        const std::optional<int> pid = leftover_pid(entry.path().filename().string(), stem);
        if (pid && !process_running(*pid) && marker_host(entry.path()) == host) stale.push_back(entry.path());
    }
    int removed = 0;
    for (const fs::path& folder : stale) {
        std::error_code failed;
        fs::remove_all(folder, failed);
        if (!failed) ++removed;
    }
    return removed;
}

void start_folder_in_place(const fs::path& given, bool force, const std::vector<std::string>& contents) {
    const fs::path output = clean(given);
    claim_output(output, force);
    unless_interrupted([&] {
        Retired old;
        bool made = false;
        try {
            old = retire(output, force);
            made = fs::create_directories(output);
            write_marker(output, &contents);
        } catch (const std::exception& e) {
            // Nothing half-made: the new folder (only its marker in it) goes, the older result comes back.
            std::error_code ignored;
            if (made) fs::remove_all(output, ignored);
            if (!old.moved_to.empty() && !exists_here(output)) fs::rename(old.moved_to, output, ignored);
            const auto* fs_error = dynamic_cast<const fs::filesystem_error*>(&e);
            throw InputError("cannot create output folder " + quoted(output) + ": " +
                             (fs_error ? fs_error->code().message() : std::string(e.what())));
        }
        std::error_code ignored;
        if (old.remove) fs::remove_all(old.moved_to, ignored);
    });
}

ResultsFolder::ResultsFolder(fs::path final_path, bool force) : final_(clean(final_path)), force_(force) {
    prepare_output(final_, force_);
    own_lock_ = take_lock(final_);
    sweep_stale_partials(final_);
    partial_ = suffixed(final_, ".partial-" + std::to_string(::getpid()));
    if (exists_here(partial_))
        refuse(partial_, "is in the way and is not a coremodal folder of this machine", "remove it yourself");
    remove_on_interrupt(partial_);
    try {
        std::error_code ec;
        fs::create_directories(partial_, ec);
        if (ec) throw InputError("cannot create " + quoted(partial_) + ": " + ec.message());
        write_marker(partial_);
    } catch (...) {
        std::error_code ignored;
        fs::remove_all(partial_, ignored);
        keep_on_interrupt(partial_);
        if (own_lock_) release_lock(final_);
        throw;
    }
}

ResultsFolder::~ResultsFolder() {
    if (!committed_) {
        std::error_code ignored;
        fs::remove_all(partial_, ignored);
    }
    keep_on_interrupt(partial_);
    if (own_lock_) release_lock(final_);
}

std::string ResultsFolder::file(const std::string& name) const { return (partial_ / name).string(); }

void ResultsFolder::commit() {
    // Under unless_interrupted: an interrupt waits for the renames, or
    // stops them before the first (the partial folder is then removed).
    // Every report.md goes out with its page one can send (output/report_html.hpp).
    write_report_html(partial_);
    try {
        const std::vector<std::string> contents = listing(partial_);
        write_marker(partial_, &contents);  // what is coremodal's in the folder
    } catch (const fs::filesystem_error& e) {
        throw InputError("cannot list what was written in " + quoted(partial_) + ": " + e.code().message());
    }
    unless_interrupted([&] {
        prepare_output(final_, force_);  // again: the place may have changed during the run
        Retired old;
        try {
            old = retire(final_, force_);
            fs::rename(partial_, final_);
        } catch (const fs::filesystem_error& e) {
            std::error_code ignored;
            if (!old.moved_to.empty() && !exists_here(final_)) fs::rename(old.moved_to, final_, ignored);
            throw InputError("cannot put the results in place at " + quoted(final_) + ": " + e.code().message());
        }
        committed_ = true;
        std::error_code ignored;
        if (old.remove) fs::remove_all(old.moved_to, ignored);
    });
    keep_on_interrupt(partial_);
}

}  // namespace coremodal
