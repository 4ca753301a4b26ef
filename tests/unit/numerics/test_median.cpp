// The median (numerics/median.hpp): the middle value of an odd count, the
// mean of the two middle values of an even count, whatever the order.
#include "numerics/median.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

TEST_CASE("The median of an odd and of an even number of values", "[converge][numerics]") {
    CHECK(median({3.0}) == 3.0);
    CHECK(median({5.0, 1.0, 3.0}) == 3.0);
    CHECK(median({4.0, 1.0, 3.0, 100.0}) == 3.5);  // one outlier (a disturbed run) does not move it
    CHECK(median({2.0, 1.0}) == 1.5);
    CHECK(median({-1.0, 7.0, 7.0, 7.0, -20.0}) == 7.0);
}
