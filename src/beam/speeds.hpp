// The speeds a printer acts on, from a roll's first bending frequency in its
// stand: Ilomäki's safe web speed (I-5) and König's critical speed (K-1/K-2),
// with the span rules they need. Computed once here for summary.json,
// report.md and `coremodal beam` alike (docs/theory/beam.md, "Symbols").
#pragma once

#include "beam/formulas.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The safety factors reported (I-5): Ilomäki's range, 0.7 without a safety
// cage, at most 0.8; it keeps the mid-span vibration within about ±5 mm.
inline constexpr double kSafeFactors[] = {0.7, 0.8};
// König's experience factor: 0.66 fitted to 76 mm cores; he recommends 0.55
// for the 150/176 core (cores wider than kKoenigLargeCore inside).
inline constexpr double kKoenigExperience = 0.66;
inline constexpr double kKoenigExperienceLargeCore = 0.55;
inline constexpr double kKoenigLargeCore = 0.12;  // m, inner diameter

// König's l: the free core length between the supports' inner edges —
// between the clamp zones, or between the chucks' inserted ends. None for a
// free scene or one clamp.
struct KoenigSpan {
    double length_m = 0;
    std::string source;  // "between the clamp zones' inner edges", ...
};
std::optional<KoenigSpan> koenig_span(const Scene& scene);

struct SafeSpeed {
    double safe = 0;       // the factor
    double v_safe_m_s = 0;  // safe · π · Dp · f1
};

struct KoenigSpeeds {
    KoenigSpan span;
    double experience = kKoenigExperience;
    std::string formula;  // "K-1" (rest paper up to 10 mm) or "K-2"
    CriticalSpeed speed;
    // v_krit with König's 0.55 for a large core, where it applies.
    std::optional<double> v_krit_large_core_m_s;
};

struct RollSpeeds {
    std::string not_given;  // why there are none ("" when given)
    double f1_hz = 0;       // the FE first bending frequency in the stand
    double dp_m = 0;        // the rest roll's outer diameter (the core's without rest paper)
    std::vector<SafeSpeed> safe;
    std::optional<KoenigSpeeds> koenig;
    bool given() const { return not_given.empty(); }
};

// The speeds of `scene` for its FE first bending frequency; `f1_missing`
// says why there is none (then f1_hz is ignored). None for a free scene: the
// speeds are for the roll in its stand.
RollSpeeds roll_speeds(const Scene& scene, double f1_hz, const std::string& f1_missing);

}  // namespace coremodal
