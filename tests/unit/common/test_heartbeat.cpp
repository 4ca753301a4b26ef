// The sign of life during long steps (common/heartbeat.hpp), with intervals of
// milliseconds instead of the real 30 s.
#include "common/heartbeat.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using namespace coremodal;
using std::chrono::milliseconds;

namespace {

// The lines a heartbeat writes, collected from its thread.
struct Lines {
    std::mutex mutex;
    std::vector<std::string> lines;
    Heartbeat::Sink sink() {
        return [this](const std::string& line) {
            const std::lock_guard lock(mutex);
            lines.push_back(line);
        };
    }
    std::vector<std::string> copy() {
        const std::lock_guard lock(mutex);
        return lines;
    }
};

}  // namespace

TEST_CASE("the heartbeat comes after 30 s, 1, 2, 4 and 8 min, then every 5 min", "[heartbeat]") {
    const std::vector<milliseconds> marks = heartbeat_marks({}, 8);
    const std::vector<long long> seconds = {30, 60, 120, 240, 480, 780, 1080, 1380};
    REQUIRE(marks.size() == seconds.size());
    for (size_t i = 0; i < marks.size(); ++i) CHECK(marks[i] == milliseconds(seconds[i] * 1000));
    // A schedule that does not grow still moves on.
    const auto flat = heartbeat_marks({milliseconds(10), 1.0, milliseconds(10)}, 3);
    CHECK(flat == std::vector<milliseconds>{milliseconds(10), milliseconds(11), milliseconds(12)});
}

TEST_CASE("a heartbeat line names the step and the time spent on it", "[heartbeat]") {
    CHECK(heartbeat_line("factorising K - sigma M", milliseconds(30'400)) ==
          "\u2026 still factorising K - sigma M: 30 s");
    CHECK(heartbeat_line("meshing", milliseconds(119'999)) == "\u2026 still meshing: 119 s");
    CHECK(heartbeat_line("meshing", milliseconds(150'000)) == "\u2026 still meshing: 2 min 30 s");
}

TEST_CASE("a heartbeat writes while its step runs and stops with it", "[heartbeat]") {
    Lines out;
    {
        const Heartbeat beat("solving", out.sink(), {milliseconds(20), 2.0, milliseconds(20)});
        // 20, 40, 60, ... ms: several lines within 300 ms even on a loaded machine.
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        while (out.copy().size() < 3 && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(milliseconds(5));
    }
    const std::vector<std::string> lines = out.copy();
    REQUIRE(lines.size() >= 3);
    for (const std::string& line : lines) CHECK(line.rfind("\u2026 still solving: ", 0) == 0);
    // Nothing after the step ended.
    std::this_thread::sleep_for(milliseconds(100));
    CHECK(out.copy().size() == lines.size());
}

TEST_CASE("a short step ends its heartbeat at once, before the first line", "[heartbeat]") {
    Lines out;
    const auto start = std::chrono::steady_clock::now();
    {
        const Heartbeat beat("meshing", out.sink());  // the real schedule: first line after 30 s
    }
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
    CHECK(out.copy().empty());
    // No printer, no thread, no trouble.
    const Heartbeat silent("assembling", Heartbeat::Sink{});
}

TEST_CASE("a printer that throws ends the heartbeat, not the program", "[heartbeat]") {
    int calls = 0;
    std::mutex mutex;
    {
        const Heartbeat beat("solving", [&](const std::string&) {
            const std::lock_guard lock(mutex);
            ++calls;
            throw std::runtime_error("broken pipe");
        }, {milliseconds(5), 1.0, milliseconds(5)});
        std::this_thread::sleep_for(milliseconds(100));
    }
    CHECK(calls == 1);
}
