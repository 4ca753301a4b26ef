// A sign of life during a long step: a 143 s factorisation (solid level,
// shift-and-invert) used to print nothing for 143 s. While a Heartbeat
// lives, a background thread writes "… still <step>: 30 s" through the
// step's progress printer at growing intervals (after 30 s, 1 min, 2 min,
// 4 min, 8 min, then every 5 min); the destructor stops it at once (RAII: the step's end,
// or an exception leaving it). The lines go where the progress lines go, and
// only when they are on (--quiet, other MPI ranks, studies' children: none).
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace coremodal {

struct HeartbeatSchedule {
    // First line after `first`; each further one when the elapsed time has
    // grown `growth` times, but at most `longest` after the last: often
    // enough to reassure, rare enough for a log.
    std::chrono::milliseconds first{30'000};
    double growth = 2.0;
    std::chrono::milliseconds longest{300'000};
};

// Elapsed times of the first `count` lines: 30 s, 60 s, 120 s, 240 s, 480 s,
// 780 s, ... for the default schedule.
std::vector<std::chrono::milliseconds> heartbeat_marks(const HeartbeatSchedule& schedule, int count);

// "… still factorising K - sigma M: 30 s" ("2 min 30 s" from two minutes on).
std::string heartbeat_line(const std::string& step, std::chrono::milliseconds elapsed);

class Heartbeat {
public:
    using Sink = std::function<void(const std::string&)>;
    // An empty `sink` starts no thread.
    Heartbeat(std::string step, Sink sink, HeartbeatSchedule schedule = {});
    ~Heartbeat();
    Heartbeat(const Heartbeat&) = delete;
    Heartbeat& operator=(const Heartbeat&) = delete;

private:
    void beat();

    std::string step_;
    Sink sink_;
    HeartbeatSchedule schedule_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopped_ = false;
    std::thread thread_;
};

}  // namespace coremodal
