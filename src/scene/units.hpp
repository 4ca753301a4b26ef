// Quantities with units in case files: "76 mm", "6.5 GPa", "920 kg/m^3",
// "1200 rpm", or plain numbers taken as SI.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

enum class Dimension { length, pressure, density, frequency, dimensionless,
                       stiffness_per_area, angle, speed, mass,
                       stiffness, rotational_stiffness,
                       unbalance,     // kg m: a mass times its distance from the axis
                       line_force,    // N/m: a force per unit length or width (a web's tension)
                       viscosity };   // Pa s: dynamic viscosity (the air dragged under a web)

const char* dimension_name(Dimension d);  // "length", "pressure (modulus)", ...
const char* si_unit(Dimension d);         // "m", "Pa", "kg/m^3", ...

// Converts "76 mm" to 0.076 for Dimension::length. Returns the SI value, or
// throws std::invalid_argument with a message such as
//   "unit 'kg' is a mass, expected a length (m, mm, cm, in)".
double parse_quantity(std::string_view text, Dimension expected);

// Formats an SI value for messages and summaries: pressures and stiffnesses
// with a readable prefix ("6.5 GPa", "130 MPa"), everything else in its SI
// unit ("0.106 m", "920 kg/m^3"); dimensionless values as plain numbers.
std::string format_quantity(double value, Dimension d);

// The units parse_quantity accepts for `d`, e.g. "m, mm, cm, in" (the common ones).
std::string accepted_units(Dimension d);

// The common units of `d` with their factor to SI, in the order above
// (for "did you mean 6.5 GPa?" when a plain number looks like a unit slip).
struct UnitFactor {
    std::string_view symbol;
    double to_si;
};
std::vector<UnitFactor> common_units(Dimension d);

}  // namespace coremodal
