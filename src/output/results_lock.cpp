#include "output/results_lock.hpp"

#include "common/error.hpp"
#include "common/warnings.hpp"
#include "output/results_paths.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace coremodal::results_lock {
namespace fs = std::filesystem;
using namespace results_paths;

namespace {

fs::path lock_path(const fs::path& output) { return suffixed(output, ".lock"); }

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", &utc);
    return text;
}

// The fields of a lock file: pid, host, started, command (one a line).
std::map<std::string, std::string> lock_fields(int fd) {
    std::string text(4096, '\0');
    const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
    text.resize(n > 0 ? static_cast<size_t>(n) : 0);
    std::map<std::string, std::string> field;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        const size_t space = line.find(' ');
        if (space != std::string::npos) field[line.substr(0, space)] = line.substr(space + 1);
    }
    return field;
}

std::string holder_text(std::map<std::string, std::string> field) {
    return "pid " + field["pid"] + " on " + field["host"] + ", since " + field["started"] + ", `" + field["command"] +
           "`";
}

// Who holds a lock, from its file: "pid 41872 on lab-pc, since ..., `coremodal run ...`".
std::string holder(int fd) {
    const auto field = lock_fields(fd);
    if (!field.count("pid") || field.at("pid").empty()) return "a process that has not said who it is yet";
    return holder_text(field);
}

// A lock file that names a holder although nobody held its flock: a run
// that ended without releasing it (SIGKILL, a power cut; the kernel dropped
// the flock with the process). Said once, so that a user who sees the file
// knows it was taken over and why that is safe.
void say_if_taken_over(int fd, const fs::path& file) {
    auto field = lock_fields(fd);
    if (!field.count("pid") || field["pid"].empty()) return;
    std::string state = "which ended without releasing it";
    if (field["host"] == host_name()) {
        const int pid = std::atoi(field["pid"].c_str());
        if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) state = "which no longer runs";
    }
    print_warnings({quoted(file) + " was left by " + holder_text(field) + ", " + state +
                    " (killed?); its lock was free, this run has taken it over"});
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

}  // namespace

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
        say_if_taken_over(fd, held.file);
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

void release_lock(const fs::path& output) { held_locks().release(lock_key(output)); }

}  // namespace coremodal::results_lock
