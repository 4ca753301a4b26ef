#include "output/results_folder.hpp"

#include "output/report_html.hpp"

#include "common/error.hpp"
#include "common/signals.hpp"

#include <fcntl.h>
#include <mpi.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <set>
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

// The line before the list of what coremodal wrote, and each entry's prefix.
constexpr const char* kContentsLine = "contents";
constexpr const char* kWrote = "wrote ";

// The marker; with `contents`, the list of what coremodal wrote. Closed and
// checked: a full disk must not leave a marker of 0 bytes behind.
void write_marker(const fs::path& folder, const std::vector<std::string>* contents = nullptr) {
    const fs::path path = folder / kResultsMarker;
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << kMarkerHeader << "\nversion " COREMODAL_VERSION "\ncommand " << command_line() << "\nhost " << host_name()
      << "\n";
    if (contents) {
        f << kContentsLine << "\n";
        for (const std::string& entry : *contents) f << kWrote << entry << "\n";
    }
    f.close();
    if (!f) throw InputError("cannot write " + path.string() + " (" + std::strerror(errno) + ")");
}

// What a folder holds, as paths relative to it ('/' separated), the marker
// left out: the list its marker gets.
std::vector<std::string> listing(const fs::path& folder) {
    std::vector<std::string> entries;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        const std::string relative = entry.path().lexically_relative(folder).generic_string();
        if (relative != kResultsMarker) entries.push_back(relative);
    }
    std::sort(entries.begin(), entries.end());
    return entries;
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

// What a marker says coremodal wrote; `listed` is false for a marker of an
// earlier version, which has no list.
struct WrittenHere {
    bool listed = false;
    std::set<std::string> paths;
};

WrittenHere written_here(const std::vector<std::string>& marker) {
    WrittenHere w;
    for (const std::string& line : marker) {
        if (line == kContentsLine) w.listed = true;
        if (w.listed && line.rfind(kWrote, 0) == 0) w.paths.insert(line.substr(std::strlen(kWrote)));
    }
    return w;
}

// "x" for what a run left of the entry x: its partial folder, the folder an
// old result was moved to, its lock (a batch's case killed mid-write).
std::string leftover_of(const std::string& relative) {
    const size_t cut = relative.find_last_of('.');
    if (cut == std::string::npos || cut == 0) return "";
    const std::string tail = relative.substr(cut + 1);
    if (tail == "lock" || tail == "previous") return relative.substr(0, cut);
    for (const char* kind : {"partial-", "old-"}) {
        const std::string prefix = kind;
        if (tail.rfind(prefix, 0) == 0 && tail.size() > prefix.size() &&
            tail.find_first_not_of("0123456789", prefix.size()) == std::string::npos)
            return relative.substr(0, cut);
    }
    return "";
}

// What `folder` (a results folder, `marker` its lines) holds that coremodal
// did not write into it, each as it is shown in a refusal: a file or folder
// not in the marker's list, a results folder nested in it (another run's,
// the user's as far as this folder is concerned). With no list (an earlier
// version's marker) only nested results folders count.
std::vector<std::string> not_written_here(const fs::path& folder, const std::vector<std::string>& marker) {
    const WrittenHere w = written_here(marker);
    const auto whole = [&](const std::string& p) { return w.paths.count(p + "/") > 0; };
    std::vector<std::string> found;
    std::error_code ec;
    fs::recursive_directory_iterator it(folder, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const std::string relative = it->path().lexically_relative(folder).generic_string();
        if (relative == kResultsMarker) continue;
        std::error_code ignored;
        const bool is_folder = fs::is_directory(it->symlink_status(ignored));
        const bool nested = is_folder && is_results_folder(it->path());
        const std::string left = leftover_of(relative);
        if (whole(relative) || (!left.empty() && (whole(left) || w.paths.count(left)))) {
            it.disable_recursion_pending();  // all in it is coremodal's
            continue;
        }
        if (w.listed ? w.paths.count(relative) > 0 : !nested) continue;
        found.push_back("'" + relative + (is_folder ? "/'" : "'") + (nested ? " (a results folder of its own)" : ""));
        it.disable_recursion_pending();
    }
    if (ec) found.push_back("what cannot be read in it (" + ec.message() + ")");
    return found;
}

// The first few of `found`, for a message.
std::string first_few(const std::vector<std::string>& found) {
    constexpr size_t kShown = 4;
    std::string text;
    for (size_t i = 0; i < found.size() && i < kShown; ++i) text += (i ? ", " : "") + found[i];
    if (found.size() > kShown) text += " and " + std::to_string(found.size() - kShown) + " more";
    return text;
}

// What in a results folder keeps it from being replaced ("" if nothing).
std::string in_the_way(const fs::path& folder) {
    const auto marker = marker_lines(folder);
    return marker ? first_few(not_written_here(folder, *marker)) : "";
}

// What may be replaced: a results folder coremodal wrote that holds nothing
// else, or an empty folder (nothing in it to lose; `mkdir out` before a run
// is common). An empty folder is removed with rmdir, which refuses if a file
// appeared.
bool replaceable(const fs::path& folder) {
    std::error_code ec;
    return (is_results_folder(folder) && in_the_way(folder).empty()) ||
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


// ---- the lock: one writer per output ------------------------------------

fs::path lock_path(const fs::path& output) { return suffixed(output, ".lock"); }

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", &utc);
    return text;
}

// Who holds a lock, from its file: "pid 41872 on lab-pc, since ..., `coremodal run ...`".
std::string holder(int fd) {
    std::string text(4096, '\0');
    const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
    text.resize(n > 0 ? static_cast<size_t>(n) : 0);
    std::map<std::string, std::string> field;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        const size_t space = line.find(' ');
        if (space != std::string::npos) field[line.substr(0, space)] = line.substr(space + 1);
    }
    if (field["pid"].empty()) return "a process that has not said who it is yet";
    return "pid " + field["pid"] + " on " + field["host"] + ", since " + field["started"] + ", `" + field["command"] +
           "`";
}

// The locks this process holds, released (their files removed, the folders
// made for them removed if still empty) when it ends. An interrupt's
// _exit skips that: the kernel releases the lock, the file stays and the
// next run takes it over.
class HeldLocks {
public:
    struct Held {
        int fd = -1;
        fs::path file;
        std::vector<fs::path> made;  // folders created for the lock file, deepest first
    };
    ~HeldLocks() {
        for (auto& [key, held] : held_) release(held);
    }
    bool holds(const std::string& key) const { return held_.count(key) > 0; }
    void add(const std::string& key, Held held) { held_[key] = std::move(held); }
    void release(const std::string& key) {
        const auto it = held_.find(key);
        if (it == held_.end()) return;
        release(it->second);
        held_.erase(it);
    }

private:
    static void release(Held& held) {
        ::unlink(held.file.c_str());  // while holding it: a waiter then finds its file gone and retries
        ::close(held.fd);
        for (const fs::path& folder : held.made) ::rmdir(folder.c_str());
    }
    std::map<std::string, Held> held_;
};

HeldLocks& held_locks() {
    static HeldLocks locks;
    return locks;
}

std::string lock_key(const fs::path& output) { return resolved(lock_path(output)).string(); }

// Takes the lock of `output` (a checked output path) unless this process
// holds it already; returns whether it was taken now. Throws InputError
// naming the holder when another process holds it.
bool take_lock(const fs::path& output) {
    const std::string key = lock_key(output);
    if (held_locks().holds(key)) return false;
    HeldLocks::Held held;
    held.file = lock_path(output);
    std::error_code ec;
    for (fs::path p = fs::absolute(parent_folder(output), ec); !ec && !exists_here(p); p = p.parent_path())
        held.made.push_back(p);
    fs::create_directories(parent_folder(output), ec);
    if (ec) refuse(output, "cannot be written", "its folder cannot be created (" + ec.message() + ")");
    // A lock file removed by its holder between our open and flock is not
    // the lock any more: try again with the new one.
    for (int attempt = 0; attempt < 10; ++attempt) {
        const int fd = ::open(held.file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd < 0)
            refuse(output, "cannot be locked",
                   "its lock file " + quoted(held.file) + " cannot be opened (" + std::strerror(errno) +
                       "); if it is yours, move it away");
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int error = errno;
            const std::string who = holder(fd);
            ::close(fd);
            if (error == EWOULDBLOCK)
                refuse(output, "is being written by another coremodal run (" + who + ")",
                       "wait until it has finished, or choose another folder");
            refuse(output, "cannot be locked", std::string("flock on ") + quoted(held.file) + ": " +
                                                   std::strerror(error) + "; choose a folder on a local disk");
        }
        struct stat opened {}, named {};
        if (::fstat(fd, &opened) != 0 || ::stat(held.file.c_str(), &named) != 0 || opened.st_ino != named.st_ino ||
            opened.st_dev != named.st_dev) {
            ::close(fd);
            continue;
        }
        const std::string who = "pid " + std::to_string(::getpid()) + "\nhost " + host_name() + "\nstarted " +
                                utc_now() + "\ncommand " + command_line() + "\n";
        // Who holds it is a courtesy to the next run: a full disk does not stop this one here.
        [[maybe_unused]] const bool noted =
            ::ftruncate(fd, 0) == 0 && ::pwrite(fd, who.data(), who.size(), 0) == static_cast<ssize_t>(who.size());
        held.fd = fd;
        held_locks().add(key, held);
        return true;
    }
    refuse(output, "cannot be locked", "its lock file " + quoted(held.file) + " keeps changing; try again");
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
        if (own_lock_) held_locks().release(lock_key(final_));
        throw;
    }
}

ResultsFolder::~ResultsFolder() {
    if (!committed_) {
        std::error_code ignored;
        fs::remove_all(partial_, ignored);
    }
    keep_on_interrupt(partial_);
    if (own_lock_) held_locks().release(lock_key(final_));
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
