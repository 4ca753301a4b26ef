// The simulator data file: what it reads, and every kind of bad data refused
// with the file, line and column and what is expected.
#include "common/error.hpp"
#include "durability/durability_data.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace coremodal;

namespace {

const std::string kHead = "# made-up test data\n# chuck_length = 100 mm\n# chuck_type = non-expanding\n";

std::string error_of(const std::string& text) {
    try {
        parse_durability_data(text, "d.csv");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("a durability file gives its points, unit and test chuck", "[durability][data]") {
    const DurabilityData d =
        parse_durability_data(kHead + "cycles,max_roll_weight [kg]\n0.5, 3000\n\n4,2500\n# a cold chuck\n120,2000\n",
                              "d.csv");
    CHECK(d.chuck_length_m == Approx(0.1));
    CHECK(d.chuck_type == "non-expanding");
    CHECK(d.weight_name == "max_roll_weight");
    CHECK(d.weight_unit == "kg");
    CHECK(d.weight_unit_newton == Approx(9.80665));
    CHECK(d.cycles == std::vector<double>{0.5, 4, 120});
    CHECK(d.weights == std::vector<double>{3000, 2500, 2000});
    CHECK(d.lines == std::vector<int>{5, 7, 9});
    CHECK(weight_unit_in_newton("kN") == 1e3);
    CHECK(weight_unit_in_newton("t") == Approx(9806.65));
    CHECK(weight_unit_in_newton("lb") == 0);
}

TEST_CASE("bad durability data is refused naming the file, line and column", "[durability][data]") {
    const std::string header = "cycles,max_roll_weight [kN]\n";
    SECTION("fewer than three points") {
        CHECK_THAT(error_of(kHead + header + "0.5,30\n10,20\n"),
                   Catch::StartsWith("d.csv:6:1: 2 data points; the power-law fit needs at least 3"));
    }
    SECTION("cycles below 0.5") {
        CHECK_THAT(error_of(kHead + header + "0.5,30\n0.25,31\n10,20\n"),
                   Catch::StartsWith("d.csv:6:1: cycles = 0.25 is below 0.5"));
    }
    SECTION("a weight that is not positive") {
        CHECK_THAT(error_of(kHead + header + "0.5,30\n2, -4\n10,20\n"),
                   Catch::StartsWith("d.csv:6:4: max_roll_weight = -4 kN must be positive"));
        CHECK_THAT(error_of(kHead + header + "0.5,0\n2,4\n10,20\n"), Catch::StartsWith("d.csv:5:5: max_roll_weight = 0 kN"));
    }
    SECTION("NaN, infinity or text") {
        CHECK_THAT(error_of(kHead + header + "0.5,30\nnan,25\n10,20\n"),
                   Catch::StartsWith("d.csv:6:1: cycles = 'nan' is not a finite number"));
        CHECK_THAT(error_of(kHead + header + "0.5,30\n2,inf\n10,20\n"),
                   Catch::StartsWith("d.csv:6:3: max_roll_weight = 'inf' is not a finite number"));
        CHECK_THAT(error_of(kHead + header + "0.5,30\n2,25 kN\n10,20\n"), Catch::StartsWith("d.csv:6:3:"));
    }
    SECTION("a row without two values") {
        CHECK_THAT(error_of(kHead + header + "0.5,30\n2\n10,20\n"),
                   Catch::StartsWith("d.csv:6:1: row has 1 values; expected two"));
    }
    SECTION("units missing or not a weight") {
        CHECK_THAT(error_of(kHead + "cycles,max_roll_weight\n0.5,30\n2,25\n10,20\n"),
                   Catch::StartsWith("d.csv:4:8: column 2 'max_roll_weight' has no unit; expected") &&
                       Catch::Contains("max_roll_weight [kN]"));
        CHECK_THAT(error_of(kHead + "cycles,max_roll_weight [mm]\n0.5,30\n2,25\n10,20\n"),
                   Catch::StartsWith("d.csv:4:25: unit 'mm' of column 2 is not a weight; expected N, kN, kg or t"));
        CHECK_THAT(error_of(kHead + "revolutions,max_roll_weight [kN]\n0.5,30\n"),
                   Catch::StartsWith("d.csv:4:1: column 1 is 'revolutions'; expected cycles"));
    }
    SECTION("the test chuck missing or wrong") {
        CHECK_THAT(error_of("# chuck_type = expanding\n" + header + "0.5,30\n2,25\n10,20\n"),
                   Catch::StartsWith("d.csv:2:1: the test chuck's length is missing"));
        CHECK_THAT(error_of("# chuck_length = 100 mm\n" + header + "0.5,30\n2,25\n10,20\n"),
                   Catch::StartsWith("d.csv:2:1: the test chuck's type is missing"));
        CHECK_THAT(error_of("# chuck_length = 100 kg\n# chuck_type = expanding\n" + header),
                   Catch::StartsWith("d.csv:1:18: chuck_length = 100 kg:"));
        CHECK_THAT(error_of("# chuck_length = 100 mm\n# chuck_type = cold\n" + header),
                   Catch::StartsWith("d.csv:2:16: chuck_type = cold: expected expanding or non-expanding"));
    }
    SECTION("every point at one cycle count") {
        CHECK_THAT(error_of(kHead + header + "3,30\n3,25\n3,20\n"),
                   Catch::StartsWith("d.csv:5:1: every point is at 3 cycles"));
    }
    SECTION("no header") {
        CHECK_THAT(error_of(kHead), Catch::StartsWith("d.csv:1:1: no header line"));
    }
}
