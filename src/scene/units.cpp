// Units of quantities in case files. One table lists every accepted unit with
// its dimension and its factor to SI; parsing, messages and the list of
// accepted units in messages all read that table.
#include "scene/units.hpp"
#include "scene/unit_symbols.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

namespace coremodal {
namespace {

struct UnitSpec {
    std::string_view symbol;  // as printed in messages
    Dimension dimension;
    double to_si;            // SI value = number * to_si / divide_by
    bool listed;             // named in "expected ..." messages (the common ones only)
    double divide_by = 1.0;  // exact decimal and 1/60 conversions: 76 mm is 76 / 1000
};

constexpr double kPi = std::numbers::pi;

// Symbols are matched after normalisation (see normalise_unit): "kg/m^3",
// "kg/m3" and "kg/m³" are the same unit. Case matters: "mPa" is not "MPa".
constexpr std::array kUnits = {
    UnitSpec{"m", Dimension::length, 1.0, true},
    UnitSpec{"mm", Dimension::length, 1.0, true, 1e3},
    UnitSpec{"cm", Dimension::length, 1.0, true, 1e2},
    UnitSpec{"in", Dimension::length, 0.0254, true},
    UnitSpec{"dm", Dimension::length, 1.0, false, 10.0},
    UnitSpec{"um", Dimension::length, 1.0, false, 1e6},
    UnitSpec{"ft", Dimension::length, 0.3048, false},

    UnitSpec{"Pa", Dimension::pressure, 1.0, true},
    UnitSpec{"kPa", Dimension::pressure, 1e3, true},
    UnitSpec{"MPa", Dimension::pressure, 1e6, true},
    UnitSpec{"GPa", Dimension::pressure, 1e9, true},
    UnitSpec{"N/mm^2", Dimension::pressure, 1e6, true},
    UnitSpec{"N/m^2", Dimension::pressure, 1.0, true},
    UnitSpec{"kN/mm^2", Dimension::pressure, 1e9, false},
    UnitSpec{"bar", Dimension::pressure, 1e5, false},
    UnitSpec{"psi", Dimension::pressure, 6894.757293168361, false},

    UnitSpec{"kg/m^3", Dimension::density, 1.0, true},
    UnitSpec{"g/cm^3", Dimension::density, 1e3, true},
    UnitSpec{"kg/dm^3", Dimension::density, 1e3, true},
    UnitSpec{"t/m^3", Dimension::density, 1e3, false},

    UnitSpec{"Hz", Dimension::frequency, 1.0, true},
    UnitSpec{"rpm", Dimension::frequency, 1.0, true, 60.0},
    UnitSpec{"1/s", Dimension::frequency, 1.0, true},
    UnitSpec{"kHz", Dimension::frequency, 1e3, false},
    UnitSpec{"1/min", Dimension::frequency, 1.0, false, 60.0},
    UnitSpec{"rad/s", Dimension::frequency, 1.0, false, 2.0 * kPi},

    UnitSpec{"N/m^3", Dimension::stiffness_per_area, 1.0, true},
    UnitSpec{"N/mm^3", Dimension::stiffness_per_area, 1e9, true},
    UnitSpec{"kN/m^3", Dimension::stiffness_per_area, 1e3, false},
    UnitSpec{"MN/m^3", Dimension::stiffness_per_area, 1e6, false},
    UnitSpec{"Pa/m", Dimension::stiffness_per_area, 1.0, false},
    UnitSpec{"MPa/mm", Dimension::stiffness_per_area, 1e9, false},

    UnitSpec{"deg", Dimension::angle, kPi, true, 180.0},
    UnitSpec{"rad", Dimension::angle, 1.0, true},
    UnitSpec{"°", Dimension::angle, kPi, false, 180.0},

    UnitSpec{"m/s", Dimension::speed, 1.0, true},
    UnitSpec{"m/min", Dimension::speed, 1.0, true, 60.0},
    UnitSpec{"km/h", Dimension::speed, 1.0, true, 3.6},
    UnitSpec{"ft/min", Dimension::speed, 0.00508, false},

    UnitSpec{"kg", Dimension::mass, 1.0, true},
    UnitSpec{"g", Dimension::mass, 1.0, true, 1e3},
    UnitSpec{"t", Dimension::mass, 1e3, true},

    UnitSpec{"N/m", Dimension::stiffness, 1.0, true},
    UnitSpec{"kN/mm", Dimension::stiffness, 1e6, true},
    UnitSpec{"N/mm", Dimension::stiffness, 1e3, true},
    UnitSpec{"kN/m", Dimension::stiffness, 1e3, false},
    UnitSpec{"MN/m", Dimension::stiffness, 1e6, false},

    // A web's tension per unit width: the symbols of a stiffness, read as
    // this dimension where a line force is expected (find_unit).
    UnitSpec{"N/m", Dimension::line_force, 1.0, true},
    UnitSpec{"kN/m", Dimension::line_force, 1e3, true},
    UnitSpec{"N/mm", Dimension::line_force, 1e3, true},

    UnitSpec{"kg*m", Dimension::unbalance, 1.0, true},
    UnitSpec{"kg*mm", Dimension::unbalance, 1.0, true, 1e3},
    UnitSpec{"g*mm", Dimension::unbalance, 1.0, true, 1e6},
    UnitSpec{"g*m", Dimension::unbalance, 1.0, false, 1e3},
    UnitSpec{"kgm", Dimension::unbalance, 1.0, false},
    UnitSpec{"kgmm", Dimension::unbalance, 1.0, false, 1e3},
    UnitSpec{"gmm", Dimension::unbalance, 1.0, false, 1e6},

    // Dynamic viscosity (air: 1.81e-5 Pa*s at room temperature, Rice & Gans' Table 3).
    UnitSpec{"Pa*s", Dimension::viscosity, 1.0, true},
    UnitSpec{"mPa*s", Dimension::viscosity, 1.0, true, 1e3},
    UnitSpec{"uPa*s", Dimension::viscosity, 1.0, true, 1e6},
    UnitSpec{"N*s/m^2", Dimension::viscosity, 1.0, false},
    UnitSpec{"cP", Dimension::viscosity, 1.0, false, 1e3},

    UnitSpec{"N*m/rad", Dimension::rotational_stiffness, 1.0, true},
    UnitSpec{"kN*m/rad", Dimension::rotational_stiffness, 1e3, true},
    UnitSpec{"MN*m/rad", Dimension::rotational_stiffness, 1e6, true},
    UnitSpec{"Nm/rad", Dimension::rotational_stiffness, 1.0, false},
    UnitSpec{"kNm/rad", Dimension::rotational_stiffness, 1e3, false},
    UnitSpec{"MNm/rad", Dimension::rotational_stiffness, 1e6, false},
};

// "kg / m³" -> "kg/m3": spaces, '^' and superscript digits do not matter;
// "µm" is "um".
std::string normalise_unit(std::string_view u) {
    std::string out;
    for (std::size_t i = 0; i < u.size(); ++i) {
        const char c = u[i];
        const std::string_view rest = u.substr(i);
        if (c == ' ' || c == '\t' || c == '^') continue;
        if (rest.starts_with("²")) {
            out += '2';
            i += std::string_view("²").size() - 1;
            continue;
        }
        if (rest.starts_with("³")) {
            out += '3';
            i += std::string_view("³").size() - 1;
            continue;
        }
        if (rest.starts_with("µ")) {
            out += 'u';
            i += std::string_view("µ").size() - 1;
            continue;
        }
        out += c;
    }
    return out;
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

// The unit of that symbol, of dimension `preferred` where two share it
// (N/m: a stiffness or a line force).
const UnitSpec* find_unit(std::string_view symbol, Dimension preferred) {
    const std::string key = normalise_unit(symbol);
    const UnitSpec* found = nullptr;
    for (const UnitSpec& u : kUnits)
        if (normalise_unit(u.symbol) == key) {
            if (u.dimension == preferred) return &u;
            if (!found) found = &u;
        }
    return found;
}

// "MPA" or "hz": the unit meant, if case is the only difference.
const UnitSpec* find_unit_ignoring_case(std::string_view symbol) {
    const std::string key = lower(normalise_unit(symbol));
    for (const UnitSpec& u : kUnits)
        if (lower(normalise_unit(u.symbol)) == key) return &u;
    return nullptr;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

std::string with_article(Dimension d) {
    const std::string name = dimension_name(d);
    const bool vowel =
        !name.empty() && std::string_view("aeiou").find(name[0]) != std::string_view::npos;
    return (vowel ? "an " : "a ") + name;
}

std::string expected_text(Dimension d) {
    if (d == Dimension::dimensionless) return "expected a plain number";
    return "expected " + with_article(d) + " (" + accepted_units(d) + ")";
}

}  // namespace

const char* dimension_name(Dimension d) {
    switch (d) {
        case Dimension::length:
            return "length";
        case Dimension::pressure:
            return "pressure (modulus)";
        case Dimension::density:
            return "density";
        case Dimension::frequency:
            return "frequency";
        case Dimension::dimensionless:
            return "dimensionless number";
        case Dimension::stiffness_per_area:
            return "stiffness per area";
        case Dimension::angle:
            return "angle";
        case Dimension::speed:
            return "speed";
        case Dimension::mass:
            return "mass";
        case Dimension::stiffness:
            return "stiffness";
        case Dimension::rotational_stiffness:
            return "rotational stiffness";
        case Dimension::unbalance:
            return "unbalance (mass times eccentricity)";
        case Dimension::line_force:
            return "force per unit width";
        case Dimension::viscosity:
            return "viscosity";
    }
    return "quantity";
}

const char* si_unit(Dimension d) {
    switch (d) {
        case Dimension::length:
            return "m";
        case Dimension::pressure:
            return "Pa";
        case Dimension::density:
            return "kg/m^3";
        case Dimension::frequency:
            return "Hz";
        case Dimension::dimensionless:
            return "";
        case Dimension::stiffness_per_area:
            return "N/m^3";
        case Dimension::angle:
            return "rad";
        case Dimension::speed:
            return "m/s";
        case Dimension::mass:
            return "kg";
        case Dimension::stiffness:
            return "N/m";
        case Dimension::rotational_stiffness:
            return "N*m/rad";
        case Dimension::unbalance:
            return "kg*m";
        case Dimension::line_force:
            return "N/m";
        case Dimension::viscosity:
            return "Pa*s";
    }
    return "";
}

std::string accepted_units(Dimension d) {
    std::string out;
    for (const UnitSpec& u : kUnits) {
        if (u.dimension != d || !u.listed) continue;
        if (!out.empty()) out += ", ";
        out += u.symbol;
    }
    return out;
}

std::vector<UnitFactor> common_units(Dimension d) {
    std::vector<UnitFactor> out;
    for (const UnitSpec& u : kUnits)
        if (u.dimension == d && u.listed) out.push_back({u.symbol, u.to_si / u.divide_by});
    return out;
}

std::vector<std::string_view> unit_symbols(Dimension d) {
    std::vector<std::string_view> out;
    for (const UnitSpec& u : kUnits)
        if (u.dimension == d) out.push_back(u.symbol);
    return out;
}

double parse_quantity(std::string_view text, Dimension expected) {
    const std::string_view s = trim(text);
    std::string_view number = s;
    if (number.starts_with('+')) number.remove_prefix(1);  // from_chars rejects '+'
    double value = 0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (ec == std::errc::result_out_of_range)
        throw std::invalid_argument("the number in '" + std::string(s) + "' is out of range; " +
                                    expected_text(expected));
    if (ec != std::errc() || !std::isfinite(value))
        throw std::invalid_argument("'" + std::string(s) +
                                    "' does not start with a finite number; " +
                                    expected_text(expected) + ", e.g. \"76 mm\"");
    const std::string_view unit = trim(std::string_view(end, number.data() + number.size() - end));

    if (unit.empty()) {
        if (expected == Dimension::dimensionless) return value;
        throw std::invalid_argument(
            "'" + std::string(s) + "' has no unit; " + expected_text(expected) +
            ", or write a plain number (no quotes) for " + si_unit(expected));
    }
    const UnitSpec* u = find_unit(unit, expected);
    if (!u) {
        std::string msg = "unknown unit '" + std::string(unit) + "'";
        if (const UnitSpec* near = find_unit_ignoring_case(unit);
            near && near->dimension == expected)
            msg += "; did you mean '" + std::string(near->symbol) + "'? (units are case-sensitive)";
        throw std::invalid_argument(msg + "; " + expected_text(expected));
    }
    if (u->dimension != expected)
        throw std::invalid_argument("unit '" + std::string(unit) + "' is " +
                                    with_article(u->dimension) + ", " + expected_text(expected));
    return value * u->to_si / u->divide_by;
}

std::string format_quantity(double value, Dimension d) {
    struct Prefix {
        double factor;
        const char* unit;
    };
    double shown = value;
    std::string unit = si_unit(d);
    if (d == Dimension::pressure || d == Dimension::stiffness_per_area) {
        const bool pressure = d == Dimension::pressure;
        const std::array<Prefix, 3> prefixes = {Prefix{1e9, pressure ? "GPa" : "GN/m^3"},
                                                Prefix{1e6, pressure ? "MPa" : "MN/m^3"},
                                                Prefix{1e3, pressure ? "kPa" : "kN/m^3"}};
        for (const Prefix& p : prefixes) {
            if (std::abs(value) >= p.factor) {
                shown = value / p.factor;
                unit = p.unit;
                break;
            }
        }
    }
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%g", shown);
    return unit.empty() ? std::string(buffer) : std::string(buffer) + " " + unit;
}

}  // namespace coremodal
