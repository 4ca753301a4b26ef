// The memory a run may take (common/free_memory.hpp): a control group's
// headroom from its files' text, and the reading on this machine against
// /proc/meminfo read here independently.
#include "common/free_memory.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <limits>
#include <string>

using namespace coremodal;

namespace {

// A /proc/meminfo field in MB, read here without the code under test.
double meminfo_mb(const std::string& field) {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    double kb = 0;
    while (meminfo >> key >> kb) {
        if (key == field + ":") return kb / 1024;
        meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    }
    return 0;
}

}  // namespace

TEST_CASE("A control group's headroom is its limit less its usage; an unlimited group has none", "[common]") {
    // 1 GiB limit, 512 MiB used: 512 MB left.
    CHECK(cgroup_headroom_mb("1073741824", "536870912").value() == Approx(512.0));
    // Over its limit (the kernel reclaims): nothing left, never negative.
    CHECK(cgroup_headroom_mb("1048576", "2097152").value() == 0.0);
    // cgroup v2 writes "max" for no limit; an empty or unreadable file says nothing.
    CHECK_FALSE(cgroup_headroom_mb("max", "4096").has_value());
    CHECK_FALSE(cgroup_headroom_mb("", "").has_value());
    // cgroup v1's "no limit" is the largest page multiple (PAGE_COUNTER_MAX
    // pages, near 2^63): no limit either, as "max" is.
    CHECK_FALSE(cgroup_headroom_mb("9223372036854771712", "4322480128").has_value());
    // A real v1 limit just below 2^62 still counts.
    CHECK(cgroup_headroom_mb("4611686018427387000", "0").has_value());
}

TEST_CASE("The memory a run may take is positive and no more than the machine's free memory", "[common]") {
    const double available = meminfo_mb("MemAvailable");
    REQUIRE(available > 0);
    const double allowed = free_memory_mb();
    CHECK(allowed > 0);
    // MemAvailable moves while the test runs: 5 % of slack.
    CHECK(allowed <= 1.05 * available);
}
