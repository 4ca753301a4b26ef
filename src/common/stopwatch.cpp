#include "common/stopwatch.hpp"

#include <sys/resource.h>

#include <fstream>
#include <string>

namespace coremodal {

double peak_memory_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

bool reset_peak_memory() {
    std::ofstream f("/proc/self/clear_refs");
    f << "5";  // 5: reset the peak resident set size (Linux >= 4.0)
    f.flush();
    return static_cast<bool>(f);
}

double peak_memory_since_reset_mb() {
    std::ifstream f("/proc/self/status");
    std::string key;
    while (f >> key) {
        if (key == "VmHWM:") {
            double kib = 0;
            if (f >> kib) return kib / 1024.0;
            break;
        }
        f.ignore(4096, '\n');
    }
    return peak_memory_mb();
}

}  // namespace coremodal
