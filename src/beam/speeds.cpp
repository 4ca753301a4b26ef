#include "beam/speeds.hpp"

#include "beam/beam_theory.hpp"

namespace coremodal {

std::optional<KoenigSpan> koenig_span(const Scene& s) {
    if (s.supports.kind == SupportKind::chucks)
        return KoenigSpan{s.core.length - s.supports.chucks.at(0).inserted_length -
                              s.supports.chucks.at(1).inserted_length,
                          "between the chucks' inserted ends"};
    if (s.supports.clamps.size() != 2) return std::nullopt;  // no span between two clamps
    return KoenigSpan{s.supports.clamps[1].z_start - s.supports.clamps[0].z_end,
                      "between the clamp zones' inner edges"};
}

RollSpeeds roll_speeds(const Scene& s, double f1_hz, const std::string& f1_missing) {
    RollSpeeds r;
    const RestRollSection section = rest_roll_section(s);
    r.dp_m = section.Dp;
    if (s.supports.kind == SupportKind::free) {
        r.not_given = "the scene is free–free, and the safe and critical speeds are for the roll in its stand "
                      "(clamped or on chucks)";
        return r;
    }
    if (!f1_missing.empty()) {
        r.not_given = f1_missing;
        return r;
    }
    r.f1_hz = f1_hz;
    for (double safe : kSafeFactors) r.safe.push_back({safe, safe_web_speed(f1_hz, section.Dp, safe)});

    const std::optional<KoenigSpan> span = koenig_span(s);
    if (!span || !(span->length_m > 0)) return r;
    const KoenigEstimate estimate = koenig_critical_speed(section, span->length_m, kKoenigExperience);
    KoenigSpeeds k;
    k.span = *span;
    k.formula = estimate.thin_paper ? "K-1" : "K-2";
    k.speed = estimate.speed;
    if (s.core.inner_diameter > kKoenigLargeCore)
        k.v_krit_large_core_m_s = estimate.speed.v_krit_m_s * kKoenigExperienceLargeCore / kKoenigExperience;
    r.koenig = k;
    return r;
}

}  // namespace coremodal
