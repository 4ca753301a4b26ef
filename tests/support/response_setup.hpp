// A forced-response setup for tests: one damping ratio, the excitation
// given, `points` web speeds from v0 to v1 (m/s) on a 196 mm roll, the
// default amplitude limit and one probe at `mid_span` (m from the left end).
#pragma once

#include "scene/response_spec.hpp"

#include <cmath>

namespace coremodal::testing {

inline ResponseSetup response_setup(double zeta, ExcitationSpec x, double v0, double v1, int points, double mid_span) {
    ResponseSetup s;
    s.damping.ratio = zeta;
    s.damping.source = "test";
    s.excitation = x;
    for (int i = 0; i < points; ++i) s.response.speeds_hz.push_back((v0 + (v1 - v0) * i / (points - 1)) / (M_PI * 0.196));
    s.response.from_web_speed = true;
    s.response.limit_m = kDefaultAmplitudeLimit;
    s.response.probes = {{"mid-span", mid_span}};
    return s;
}

}  // namespace coremodal::testing
