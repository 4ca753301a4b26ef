#include "common/free_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

namespace coremodal {
namespace {

std::string first_line(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

// MemAvailable in MB, 0 when unknown.
double mem_available_mb() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    double kb = 0;
    while (meminfo >> key >> kb)
        if (key == "MemAvailable:") return kb / 1024;
        else meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    return 0;
}

std::optional<double> least(std::optional<double> a, std::optional<double> b) {
    if (!a) return b;
    if (!b) return a;
    return std::min(*a, *b);
}

// This process's control group headroom, from each line of
// /proc/self/cgroup: "0::/path" (v2, mounted at /sys/fs/cgroup or, on a
// hybrid system, /sys/fs/cgroup/unified) and "N:memory:/path" (v1).
std::optional<double> own_cgroup_headroom_mb() {
    std::ifstream groups("/proc/self/cgroup");
    std::optional<double> headroom;
    std::string line;
    while (std::getline(groups, line)) {
        const auto colon = line.find(':');
        const auto second = colon == std::string::npos ? colon : line.find(':', colon + 1);
        if (second == std::string::npos) continue;
        const std::string controllers = line.substr(colon + 1, second - colon - 1);
        const std::string path = line.substr(second + 1);
        if (controllers.empty()) {
            for (const std::string root : {"/sys/fs/cgroup", "/sys/fs/cgroup/unified"})
                headroom = least(headroom, cgroup_headroom_mb(first_line(root + path + "/memory.max"),
                                                              first_line(root + path + "/memory.current")));
        } else if (controllers.find("memory") != std::string::npos) {
            const std::string dir = "/sys/fs/cgroup/memory" + path;
            headroom = least(headroom, cgroup_headroom_mb(first_line(dir + "/memory.limit_in_bytes"),
                                                          first_line(dir + "/memory.usage_in_bytes")));
        }
    }
    return headroom;
}

}  // namespace

std::optional<double> cgroup_headroom_mb(const std::string& limit, const std::string& usage) {
    double limit_bytes = 0, usage_bytes = 0;
    std::istringstream l(limit), u(usage);
    // cgroup v1 writes "no limit" as a number near 2^63 (PAGE_COUNTER_MAX pages).
    constexpr double kNoLimit = 0x1p62;
    if (!(l >> limit_bytes) || !(u >> usage_bytes) || limit_bytes <= 0 || limit_bytes >= kNoLimit) return std::nullopt;
    return std::max(0.0, limit_bytes - usage_bytes) / kBytesPerMb;
}

std::optional<AddressSpace> address_space_limit() {
    struct rlimit limit {};
    if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    // /proc/self/statm: the first field is the mapped size in pages.
    std::ifstream statm("/proc/self/statm");
    double pages = 0;
    statm >> pages;
    return AddressSpace{double(limit.rlim_cur) / kBytesPerMb, pages * double(::sysconf(_SC_PAGESIZE)) / kBytesPerMb};
}

std::string out_of_memory_text(double needed_mb, const std::string& estimate_of) {
    auto mb = [](double v) { return std::to_string(static_cast<long>(v + 0.5)) + " MB"; };
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    const double peak_mb = usage.ru_maxrss / 1024.0;  // KiB on Linux
    std::string text = "out of memory: ";
    text += needed_mb > 0 ? "the run needs about " + mb(needed_mb) + " (" + estimate_of + "), "
                          : "an allocation failed after the run had reached " + mb(peak_mb) + " resident, ";
    std::vector<std::string> had;
    if (const std::optional<AddressSpace> space = address_space_limit())
        had.push_back(mb(space->headroom_mb()) + " left under the address-space limit of " + mb(space->limit_mb) +
                      " (ulimit -v)");
    if (const double machine = mem_available_mb(); machine > 0) had.push_back(mb(machine) + " free on the machine");
    if (const std::optional<double> group = own_cgroup_headroom_mb()) had.push_back(mb(*group) + " left in its control group");
    text += "and it had ";
    for (size_t i = 0; i < had.size(); ++i) text += (i ? ", " : "") + had[i];
    if (had.empty()) text += "no more";
    return text +
           ". Give it more memory (a larger ulimit -v or job allocation), or ask for less: a coarser mesh "
           "(--mesh coarse), a lighter model level (--model harmonic or beam), fewer modes ([analysis] modes), or "
           "-max_memory_mb MB to let the factor go out of core";
}

double free_memory_mb() {
    const double machine = mem_available_mb();
    std::optional<double> headroom =
        least(machine > 0 ? std::optional<double>(machine) : std::nullopt, own_cgroup_headroom_mb());
    if (const std::optional<AddressSpace> space = address_space_limit()) headroom = least(headroom, space->headroom_mb());
    return headroom.value_or(0);
}

}  // namespace coremodal
