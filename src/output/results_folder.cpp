#include "output/results_folder.hpp"

#include "common/error.hpp"
#include "common/signals.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace coremodal {
namespace fs = std::filesystem;

namespace {

// The marker's first line: what makes a folder coremodal's.
constexpr const char* kMarkerHeader = "coremodal results folder";

// The output path as given, without a trailing separator ("out/" is "out";
// a partial folder "out/.partial-1" would be inside it) or "." and "..".
fs::path clean(const fs::path& p) {
    fs::path q = p.lexically_normal();
    if (!q.has_filename() && q.has_relative_path()) q = q.parent_path();
    return q;
}

fs::path suffixed(const fs::path& p, const std::string& suffix) {
    fs::path q = p;
    q += suffix;
    return q;
}

// A path in a message: 'out/tiny'.
std::string quoted(const fs::path& p) {
    std::string q = "'";
    q += p.string();
    q += "'";
    return q;
}

fs::path parent_folder(const fs::path& p) { return p.has_parent_path() ? p.parent_path() : fs::path("."); }

bool exists_here(const fs::path& p) {  // without following a symbolic link
    std::error_code ec;
    return fs::exists(fs::symlink_status(p, ec));
}

fs::path resolved(const fs::path& p) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(p, ec);
    const fs::path real = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : real;
}

std::string host_name() {
    char name[256] = {};
    ::gethostname(name, sizeof name - 1);
    return name;
}

// This process's command line, as /proc/self/cmdline holds it.
std::string command_line() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    while (!text.empty() && text.back() == '\0') text.pop_back();
    for (char& c : text)
        if (c == '\0' || c == '\n') c = ' ';
    return text;
}

void write_marker(const fs::path& folder) {
    const fs::path path = folder / kResultsMarker;
    std::ofstream f(path);
    f << kMarkerHeader << "\nversion " COREMODAL_VERSION "\ncommand " << command_line() << "\nhost " << host_name()
      << "\n";
    if (!f) throw InputError("cannot write " + path.string());
}

// The marker's lines, if `folder` is a folder (not a link) holding one.
std::optional<std::vector<std::string>> marker_lines(const fs::path& folder) {
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(folder, ec))) return std::nullopt;
    std::ifstream in(folder / kResultsMarker);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    if (lines.empty() || lines.front() != kMarkerHeader) return std::nullopt;
    return lines;
}

// What may be replaced: a results folder coremodal wrote, or an empty
// folder (nothing in it to lose; `mkdir out` before a run is common). An
// empty folder is removed with rmdir, which refuses if a file appeared.
bool replaceable(const fs::path& folder) {
    std::error_code ec;
    return is_results_folder(folder) ||
           (fs::is_directory(fs::symlink_status(folder, ec)) && fs::is_empty(folder, ec) && !ec);
}

[[noreturn]] void refuse(const fs::path& output, const std::string& why, const std::string& what_to_do) {
    throw InputError("output folder " + quoted(output) + " " + why + ": " + what_to_do);
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

}  // namespace

bool is_results_folder(const fs::path& folder) { return marker_lines(folder).has_value(); }

std::optional<std::string> marker_host(const fs::path& folder) {
    const auto lines = marker_lines(folder);
    if (!lines) return std::nullopt;
    for (const std::string& line : *lines)
        if (line.rfind("host ", 0) == 0) return line.substr(5);
    return std::nullopt;
}

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
    if (fs::exists(status) && !replaceable(output))
        refuse(output, std::string("exists and was not written by coremodal (no ") + kResultsMarker + " file in it)",
               "coremodal only replaces its own results; " + kChooseAnother + ", or move or remove it yourself");
    const fs::path previous = previous_path(output);
    if (fs::exists(status) && !force && exists_here(previous) && !replaceable(previous))
        refuse(output, "would be kept as " + quoted(previous) + ", which is not a coremodal results folder",
               "move or remove " + quoted(previous) + " yourself, or give --force to replace " +
                   quoted(output) + " without keeping it");
    require_writable_place(output);
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

void start_folder_in_place(const fs::path& given, bool force) {
    const fs::path output = clean(given);
    prepare_output(output, force);
    unless_interrupted([&] {
        try {
            const Retired old = retire(output, force);
            if (old.remove) fs::remove_all(old.moved_to);
            fs::create_directories(output);
        } catch (const fs::filesystem_error& e) {
            throw InputError("cannot create output folder " + quoted(output) + ": " + e.code().message());
        }
        write_marker(output);
    });
}

ResultsFolder::ResultsFolder(fs::path final_path, bool force) : final_(clean(final_path)), force_(force) {
    prepare_output(final_, force_);
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
        throw;
    }
}

ResultsFolder::~ResultsFolder() {
    if (!committed_) {
        std::error_code ignored;
        fs::remove_all(partial_, ignored);
    }
    keep_on_interrupt(partial_);
}

std::string ResultsFolder::file(const std::string& name) const { return (partial_ / name).string(); }

void ResultsFolder::commit() {
    // Under unless_interrupted: an interrupt waits for the renames, or
    // stops them before the first (the partial folder is then removed).
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
