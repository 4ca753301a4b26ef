// Numbers in messages, tables and reports: one place for the formatting
// that several commands share.
#pragma once

#include <cstdio>
#include <optional>
#include <string>

namespace coremodal {

// v with `digits` significant digits ("%.4g"): 61.44, 3.1e+10.
inline std::string significant(double v, int digits = 4) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

// v through a printf format taking one double, e.g. formatted("%.2f", v).
inline std::string formatted(const char* format, double v) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

// Ten significant digits, for CSV, JSON and tables: a reader gets back what
// was computed.
inline std::string ten_digits(double v) { return significant(v, 10); }

// An optional value through a printf format, or "" when absent.
inline std::string optional_number(const std::optional<double>& v, const char* format = "%.10g") {
    return v ? formatted(format, *v) : "";
}

// Millimetres per metre: the unit of diameters, bows and amplitudes in reports.
inline constexpr double kMmPerM = 1e3;

// A length in metres shown in millimetres for people: "5.25 mm".
inline std::string millimetres(double metres, int digits = 4) { return significant(metres * kMmPerM, digits) + " mm"; }

// A web speed for people, in both units presses use: "12.5 m/s (750 m/min)".
inline std::string web_speed(double v) { return significant(v) + " m/s (" + significant(v * 60) + " m/min)"; }

// Revolutions per minute per hertz.
inline constexpr double kRpmPerHz = 60.0;

// A rotation speed in Hz shown in rpm for people: "1234.5 rpm".
inline std::string rpm(double speed_hz) { return significant(speed_hz * kRpmPerHz, 5) + " rpm"; }

// A share as a percentage: "2.5 %".
inline std::string percent(double share, int digits = 3) { return significant(100 * share, digits) + " %"; }

// A duration for people: "95.2 s" below two minutes, "12.5 min" above.
inline std::string minutes_or_seconds(double s) {
    return s < 120 ? significant(s, 3) + " s" : significant(s / 60, 3) + " min";
}

}  // namespace coremodal
