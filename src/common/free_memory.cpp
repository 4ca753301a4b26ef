#include "common/free_memory.hpp"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

namespace coremodal {
namespace {

constexpr double kBytesPerMb = 1024.0 * 1024.0;

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
    if (!(l >> limit_bytes) || !(u >> usage_bytes) || limit_bytes <= 0) return std::nullopt;
    return std::max(0.0, limit_bytes - usage_bytes) / kBytesPerMb;
}

double free_memory_mb() {
    const double machine = mem_available_mb();
    return least(machine > 0 ? std::optional<double>(machine) : std::nullopt, own_cgroup_headroom_mb()).value_or(0);
}

}  // namespace coremodal
