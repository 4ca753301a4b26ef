#include "common/process_folders.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace coremodal {
namespace fs = std::filesystem;

bool coremodal_running(pid_t pid) {
    // /proc/<pid>/stat: "<pid> (<name>) <state> ...". A zombie (Z, or X
    // dead) has ended: killed, not yet reaped by its new parent.
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!stat || !std::getline(stat, line)) return false;
    const size_t open = line.find('('), close = line.rfind(')');
    if (open == std::string::npos || close == std::string::npos || close + 2 >= line.size()) return false;
    const char state = line[close + 2];
    return line.compare(open + 1, 9, "coremodal") == 0 && state != 'Z' && state != 'X';
}

fs::path process_folder(const fs::path& parent, std::string_view prefix, pid_t pid) {
    return parent / (std::string(prefix) + std::to_string(pid));
}

int remove_folders_of_dead_processes(const fs::path& parent, std::string_view prefix) {
    int removed = 0;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(parent, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0 || name.size() == prefix.size() || name.size() > prefix.size() + 9 ||
            name.find_first_not_of("0123456789", prefix.size()) != std::string::npos)
            continue;
        struct stat st {};
        if (::lstat(entry.path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::geteuid()) continue;
        const pid_t pid = static_cast<pid_t>(std::stol(name.substr(prefix.size())));
        if (pid == ::getpid() || coremodal_running(pid)) continue;
        std::error_code failed;
        if (fs::remove_all(entry.path(), failed) > 0 && !failed) ++removed;
    }
    return removed;
}

}  // namespace coremodal
