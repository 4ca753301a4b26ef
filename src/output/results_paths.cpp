#include "output/results_paths.hpp"

#include "common/error.hpp"

#include <unistd.h>

#include <fstream>
#include <iterator>

namespace coremodal::results_paths {
namespace fs = std::filesystem;

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

std::string quoted(const fs::path& p) {
    std::string q = "'";
    q += p.string();
    q += "'";
    return q;
}

fs::path parent_folder(const fs::path& p) { return p.has_parent_path() ? p.parent_path() : fs::path("."); }

bool exists_here(const fs::path& p) {
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

std::string command_line() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    while (!text.empty() && text.back() == '\0') text.pop_back();
    for (char& c : text)
        if (c == '\0' || c == '\n') c = ' ';
    return text;
}

[[noreturn]] void refuse(const fs::path& output, const std::string& why, const std::string& what_to_do) {
    throw InputError("output folder " + quoted(output) + " " + why + ": " + what_to_do);
}

}  // namespace coremodal::results_paths
