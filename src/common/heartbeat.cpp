#include "common/heartbeat.hpp"

#include <algorithm>
#include <cmath>
#include <system_error>

namespace coremodal {

namespace {

using std::chrono::milliseconds;

// The mark after `at` (0: none yet): `growth` times the elapsed time, at most
// `longest` after it, and always later.
milliseconds next_mark(milliseconds at, const HeartbeatSchedule& s) {
    if (at.count() == 0) return std::max(s.first, milliseconds(1));
    const auto grown = milliseconds(static_cast<long long>(std::llround(double(at.count()) * s.growth)));
    return std::clamp(grown, at + milliseconds(1), at + std::max(s.longest, milliseconds(1)));
}

}  // namespace

std::vector<milliseconds> heartbeat_marks(const HeartbeatSchedule& schedule, int count) {
    std::vector<milliseconds> marks;
    milliseconds at{0};
    for (int i = 0; i < count; ++i) marks.push_back(at = next_mark(at, schedule));
    return marks;
}

std::string heartbeat_line(const std::string& step, milliseconds elapsed) {
    const long long s = elapsed.count() / 1000;
    constexpr long long kMinutesFrom = 120;  // "90 s" reads faster than "1 min 30 s"
    const std::string time = s < kMinutesFrom ? std::to_string(s) + " s"
                                              : std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
    return "\u2026 still " + step + ": " + time;
}

Heartbeat::Heartbeat(std::string step, Sink sink, HeartbeatSchedule schedule)
    : step_(std::move(step)), sink_(std::move(sink)), schedule_(schedule) {
    if (!sink_) return;
    try {
        thread_ = std::thread([this] { beat(); });
    } catch (const std::system_error&) {
        // No thread to spare: the step runs all the same, silently, as before.
    }
}

Heartbeat::~Heartbeat() {
    {
        const std::lock_guard lock(mutex_);
        stopped_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void Heartbeat::beat() {
    const auto start = std::chrono::steady_clock::now();
    milliseconds at{0};
    std::unique_lock lock(mutex_);
    for (;;) {
        at = next_mark(at, schedule_);
        if (wake_.wait_until(lock, start + at, [this] { return stopped_; })) return;
        const auto elapsed = std::chrono::duration_cast<milliseconds>(std::chrono::steady_clock::now() - start);
        try {
            sink_(heartbeat_line(step_, elapsed));
        } catch (...) {
            return;  // a printer that fails (a closed pipe) ends the heartbeat, not the run
        }
    }
}

}  // namespace coremodal
