#include "output/results_marker.hpp"

#include "common/error.hpp"
#include "output/results_paths.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>

namespace coremodal {
namespace fs = std::filesystem;
using namespace results_paths;

namespace {

// The marker's first line: what makes a folder coremodal's.
constexpr const char* kMarkerHeader = "coremodal results folder";

// The line before the list of what coremodal wrote, and each entry's prefix.
constexpr const char* kContentsLine = "contents";
constexpr const char* kWrote = "wrote ";



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

}  // namespace

bool is_results_folder(const fs::path& folder) { return marker_lines(folder).has_value(); }

std::optional<std::string> marker_host(const fs::path& folder) {
    const auto lines = marker_lines(folder);
    if (!lines) return std::nullopt;
    for (const std::string& line : *lines)
        if (line.rfind("host ", 0) == 0) return line.substr(5);
    return std::nullopt;
}

namespace results_marker {

void write_marker(const fs::path& folder, const std::vector<std::string>* contents) {
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

std::vector<std::string> listing(const fs::path& folder) {
    std::vector<std::string> entries;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        const std::string relative = entry.path().lexically_relative(folder).generic_string();
        if (relative != kResultsMarker) entries.push_back(relative);
    }
    std::sort(entries.begin(), entries.end());
    return entries;
}

std::string in_the_way(const fs::path& folder) {
    const auto marker = marker_lines(folder);
    return marker ? first_few(not_written_here(folder, *marker)) : "";
}

}  // namespace results_marker
}  // namespace coremodal
