#include "numerics/median.hpp"

#include "common/error.hpp"

#include <algorithm>

namespace coremodal {

double median(std::vector<double> values) {
    COREMODAL_ASSERT(!values.empty());
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace coremodal
