#include "scene/units.hpp"

#include <catch2/catch.hpp>

#include <numbers>
#include <stdexcept>
#include <string>

using namespace coremodal;

namespace {

std::string message_of(std::string_view text, Dimension d) {
    try {
        parse_quantity(text, d);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("Quantities with units convert to SI", "[scene][units]") {
    SECTION("lengths") {
        CHECK(parse_quantity("76 mm", Dimension::length) == 0.076);
        CHECK(parse_quantity("1.5 m", Dimension::length) == 1.5);
        CHECK(parse_quantity("15.8mm", Dimension::length) == Approx(0.0158).epsilon(1e-15));
        CHECK(parse_quantity("3 in", Dimension::length) == Approx(0.0762).epsilon(1e-15));
        CHECK(parse_quantity("  25 cm ", Dimension::length) == Approx(0.25).epsilon(1e-15));
        CHECK(parse_quantity("+2e-3 m", Dimension::length) == 2e-3);
    }
    SECTION("moduli") {
        CHECK(parse_quantity("6.5 GPa", Dimension::pressure) == 6.5e9);
        CHECK(parse_quantity("130 MPa", Dimension::pressure) == 130e6);
        CHECK(parse_quantity("1800 N/mm^2", Dimension::pressure) == 1.8e9);
        CHECK(parse_quantity("1800 N/mm2", Dimension::pressure) == 1.8e9);
        CHECK(parse_quantity("1800 N/mm²", Dimension::pressure) == 1.8e9);
        CHECK(parse_quantity("5 kPa", Dimension::pressure) == 5e3);
        CHECK(parse_quantity("7 N/m^2", Dimension::pressure) == 7.0);
    }
    SECTION("densities") {
        CHECK(parse_quantity("920 kg/m^3", Dimension::density) == 920.0);
        CHECK(parse_quantity("1.2 kg/dm^3", Dimension::density) == Approx(1200.0).epsilon(1e-15));
        CHECK(parse_quantity("1.35 g/cm³", Dimension::density) == Approx(1350.0).epsilon(1e-15));
    }
    SECTION("frequencies and rotation speeds") {
        CHECK(parse_quantity("500 Hz", Dimension::frequency) == 500.0);
        CHECK(parse_quantity("1200 rpm", Dimension::frequency) == 20.0);
        CHECK(parse_quantity("50 1/s", Dimension::frequency) == 50.0);
    }
    SECTION("other dimensions") {
        CHECK(parse_quantity("2e7 N/m^3", Dimension::stiffness_per_area) == 2e7);
        CHECK(parse_quantity("30 deg", Dimension::angle) == Approx(std::numbers::pi / 6));
        CHECK(parse_quantity("14 m/s", Dimension::speed) == 14.0);
        CHECK(parse_quantity("3 kg", Dimension::mass) == 3.0);
        CHECK(parse_quantity("0.3", Dimension::dimensionless) == 0.3);
    }
    SECTION("viscosities (air: 1.81e-5 Pa*s, [traction])") {
        CHECK(parse_quantity("1.81e-5 Pa*s", Dimension::viscosity) == 1.81e-5);
        CHECK(parse_quantity("0.0181 mPa * s", Dimension::viscosity) == Approx(1.81e-5).epsilon(1e-15));
        CHECK(parse_quantity("18.1 µPa*s", Dimension::viscosity) == Approx(1.81e-5).epsilon(1e-15));
        CHECK(parse_quantity("0.0181 cP", Dimension::viscosity) == Approx(1.81e-5).epsilon(1e-15));
        CHECK_THROWS_WITH(parse_quantity("1.8e-5 Pa", Dimension::viscosity),
                          "unit 'Pa' is a pressure (modulus), expected a viscosity (Pa*s, mPa*s, uPa*s)");
    }
}

TEST_CASE("Bad quantities say what was expected", "[scene][units]") {
    SECTION("A unit of the wrong dimension names both dimensions") {
        CHECK(message_of("76 kg", Dimension::length) ==
              "unit 'kg' is a mass, expected a length (m, mm, cm, in)");
        CHECK_THAT(message_of("6.5 mm", Dimension::pressure),
                   Catch::Contains(
                       "unit 'mm' is a length, expected a pressure (modulus) (Pa, kPa, MPa, GPa"));
        CHECK_THAT(message_of("500 Hz", Dimension::density),
                   Catch::Contains("is a frequency, expected a density (kg/m^3"));
    }
    SECTION("An unknown unit is named; a case slip gets a suggestion") {
        CHECK_THAT(message_of("76 furlongs", Dimension::length),
                   Catch::Contains("unknown unit 'furlongs'"));
        CHECK_THAT(message_of("6.5 gpa", Dimension::pressure),
                   Catch::Contains("did you mean 'GPa'?"));
        CHECK_THAT(message_of("6.5 mPa", Dimension::pressure),
                   Catch::Contains("did you mean 'MPa'?"));
    }
    SECTION("A missing number or a missing unit is refused") {
        CHECK_THAT(message_of("mm", Dimension::length),
                   Catch::Contains("does not start with a finite number"));
        CHECK_THAT(message_of("", Dimension::length),
                   Catch::Contains("does not start with a finite number"));
        CHECK_THAT(message_of("76", Dimension::length), Catch::Contains("'76' has no unit"));
        CHECK_THAT(message_of("nan m", Dimension::length), Catch::Contains("finite number"));
        CHECK_THAT(message_of("inf Pa", Dimension::pressure), Catch::Contains("finite number"));
        CHECK_THAT(message_of("1e999 m", Dimension::length), Catch::Contains("out of range"));
    }
}

TEST_CASE("Quantities print with readable units", "[scene][units]") {
    CHECK(format_quantity(0.106, Dimension::length) == "0.106 m");
    CHECK(format_quantity(6.5e9, Dimension::pressure) == "6.5 GPa");
    CHECK(format_quantity(130e6, Dimension::pressure) == "130 MPa");
    CHECK(format_quantity(920, Dimension::density) == "920 kg/m^3");
    CHECK(format_quantity(0.3, Dimension::dimensionless) == "0.3");
}
