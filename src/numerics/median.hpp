// The median of a sample: the middle value, or the mean of the two middle
// values for an even count. Used for timings of repeated runs, where one run
// disturbed by another process must not move the result.
#pragma once

#include <vector>

namespace coremodal {

// Needs at least one value (asserted).
double median(std::vector<double> values);

}  // namespace coremodal
