// Scenes for verification tests, built in code so that the solver is tested
// independently of the case-file parser.
#pragma once

#include "app/run_case.hpp"
#include "scene/scene.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace coremodal::testing {

inline Scene steel_tube(double d_out, double d_in, double length, int wall, int around, int along,
                        int n_modes = 12) {
    Scene s;
    s.name = "steel_tube";
    s.source_file = "(test)";
    s.core = {d_in, d_out, length, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850)};
    s.supports.kind = SupportKind::free;
    s.mesh.level = "custom";
    s.mesh.n_wall = wall;
    s.mesh.n_around = around;
    s.mesh.n_along = along;
    s.analysis.n_modes = n_modes;
    return s;
}

inline Scene clamp_both_ends(Scene s, double clamp_length) {
    s.supports.kind = SupportKind::clamped;
    s.supports.clamps = {{"left", 0.0, clamp_length}, {"right", s.core.length - clamp_length, s.core.length}};
    return s;
}

inline RunReport solve_quietly(const Scene& s) {
    RunOptions options;
    options.quiet = true;
    options.write_results = false;
    return run_scene(s, options);
}

// The k-th (1-based) mode of a type, counting each degenerate pair once.
inline const Mode& nth_of_type(const RunReport& r, const std::string& type, int k = 1) {
    int seen = 0;
    double last = -1;
    for (const auto& m : r.modes.modes) {
        if (m.label.type != type) continue;
        if (last > 0 && std::abs(m.frequency_hz - last) < 1e-6 * last) continue;  // partner of a pair
        last = m.frequency_hz;
        if (++seen == k) return m;
    }
    throw std::runtime_error("no mode " + std::to_string(k) + " of type " + type);
}

}  // namespace coremodal::testing
