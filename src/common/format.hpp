// Numbers in messages, tables and reports: one place for the formatting
// that several commands share.
#pragma once

#include <cstdio>
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

// A duration for people: "95.2 s" below two minutes, "12.5 min" above.
inline std::string minutes_or_seconds(double s) {
    return s < 120 ? significant(s, 3) + " s" : significant(s / 60, 3) + " min";
}

}  // namespace coremodal
