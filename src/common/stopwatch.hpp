// Wall-clock timing of pipeline stages and the process's peak memory.
#pragma once

#include <chrono>

namespace coremodal {

class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    // Seconds since construction or the last lap.
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - start_).count();
        start_ = now;
        return s;
    }

private:
    std::chrono::steady_clock::time_point start_;
};

// Peak resident set size of this process so far, in MiB.
double peak_memory_mb();

// For several runs in one process (coremodal converge): resets the kernel's
// peak resident set to the current one (Linux /proc/self/clear_refs); false
// when the kernel does not allow it. peak_memory_since_reset_mb() then reads
// the peak since the reset (VmHWM), or peak_memory_mb() if it cannot.
bool reset_peak_memory();
double peak_memory_since_reset_mb();

}  // namespace coremodal
