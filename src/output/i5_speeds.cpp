#include "output/i5_speeds.hpp"

#include "common/format.hpp"

namespace coremodal {

std::string i5_speed_lines(const RollSpeeds& s) {
    if (!s.given()) return "I-5 safe web speed: not given (" + s.not_given + ").\n";
    std::string out;
    for (const SafeSpeed& v : s.safe)
        out += "- I-5 safe web speed (factor " + significant(v.safe, 2) + ", first bending at rest " +
               significant(s.f1_hz, 5) + " Hz, Dp " + significant(s.dp_m * 1e3, 4) + " mm): " +
               significant(v.v_safe_m_s, 4) + " m/s\n";
    return out;
}

}  // namespace coremodal
