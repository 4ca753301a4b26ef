// The folders a process names by its number, removed once it is gone
// (common/process_folders.hpp): only this user's real folders of processes
// that no longer run.
#include "common/process_folders.hpp"

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace coremodal;

namespace {

// The number of a process that has ended (a child started and reaped).
pid_t ended_process() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    ::waitpid(pid, nullptr, 0);
    return pid;
}

}  // namespace

TEST_CASE("Folders of processes that are gone are removed, nothing else", "[process_folders]") {
    const fs::path parent = fs::temp_directory_path() / ("coremodal_test_process_folders_" + std::to_string(::getpid()));
    fs::remove_all(parent);
    fs::create_directories(parent);
    constexpr std::string_view prefix = "coremodal-x-";

    const fs::path dead = process_folder(parent, prefix, ended_process());
    fs::create_directories(dead / "inner");
    std::ofstream(dead / "inner" / "segment") << "left by a killed process";
    const fs::path mine = process_folder(parent, prefix, ::getpid());  // alive: this test is a coremodal_tests
    fs::create_directories(mine);
    const fs::path not_a_number = parent / "coremodal-x-12ab";
    fs::create_directories(not_a_number);
    const fs::path other_prefix = process_folder(parent, "coremodal-y-", ended_process());
    fs::create_directories(other_prefix);
    const fs::path a_file = process_folder(parent, prefix, ended_process());
    std::ofstream(a_file) << "a file, not a folder";
    // A symbolic link of that name: neither it nor where it points is removed.
    const fs::path target = parent / "target";
    fs::create_directories(target);
    std::ofstream(target / "keep") << "the user's";
    const fs::path link = process_folder(parent, prefix, ended_process());
    fs::create_directory_symlink(target, link);

    CHECK(remove_folders_of_dead_processes(parent, prefix) == 1);
    CHECK_FALSE(fs::exists(dead));
    for (const fs::path& kept : {mine, not_a_number, other_prefix, a_file, target / "keep"}) {
        INFO(kept);
        CHECK(fs::exists(kept));
    }
    CHECK(fs::is_symlink(link));

    // Another user's folder of a process that is gone stays (as root: give it away).
    if (::geteuid() == 0) {
        const fs::path theirs = process_folder(parent, prefix, ended_process());
        fs::create_directories(theirs);
        REQUIRE(::chown(theirs.c_str(), 65534, 65534) == 0);
        CHECK(remove_folders_of_dead_processes(parent, prefix) == 0);
        CHECK(fs::exists(theirs));
    }
    fs::remove_all(parent);
}
