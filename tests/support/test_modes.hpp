// A labelled mode without a shape, for tests of what is built from mode
// tables (reports, tracking, pairing).
#pragma once

#include "modes/mode_set.hpp"

#include <string>

namespace coremodal::testing {

inline Mode mode(int index, double f, const std::string& type, int n = 1, int m = 0) {
    Mode x;
    x.index = index;
    x.frequency_hz = f;
    x.label.type = type;
    x.label.n = n;
    x.label.m = m;
    x.label.dominant_share = 0.9;
    return x;
}

}  // namespace coremodal::testing
