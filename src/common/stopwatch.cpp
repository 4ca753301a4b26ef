#include "common/stopwatch.hpp"

#include <sys/resource.h>

namespace coremodal {

double peak_memory_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace coremodal
