#include "output/i5_speeds.hpp"

#include "common/format.hpp"

namespace coremodal {

toml::table i5_speeds_json(const RollSpeeds& s) {
    toml::table t;
    if (!s.given()) {
        t.insert("not_given", s.not_given);
        return t;
    }
    t.insert("first_bending_at_rest_hz", s.f1_hz);
    t.insert("dp_m", s.dp_m);
    toml::array safe;
    for (const SafeSpeed& v : s.safe) safe.push_back(toml::table{{"factor", v.safe}, {"v_safe_m_s", v.v_safe_m_s}});
    t.insert("i5_safe_web_speed", safe);
    return t;
}

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
