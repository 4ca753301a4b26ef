// The verdict's warnings and notes (analyses/limits/limits.hpp, step 5):
// the knife edge, criteria that disagree beyond their bands, a mode whose
// label changes along the unwind; what every criterion is and what the
// verdict does not include.
#include "analyses/limits/limits_band.hpp"
#include "common/format.hpp"
#include "common/join.hpp"

#include <cmath>

namespace coremodal {
namespace {

// The forced response's self-check, once per verdict (docs/how-to/limits.md, "Speed").
std::string checks_note(const LimitsChecks& c) {
    const ResponseChecks& k = c.checks;
    return "the forced response's superposition checked once, at " + significant(c.diameter_m * 1e3, 5) + " mm (" +
           std::to_string(k.speeds_checked) + " speeds): the truncated sum against " +
           (k.complete_basis
                ? "the complete basis " + significant(k.truncation_max_relative, 2) +
                      ", the complete basis against the direct solve " + significant(k.direct_max_relative, 2) +
                      " at " + std::to_string(k.direct_speeds_checked) + " of them"
                : "the direct solve " + significant(k.direct_max_relative, 2)) +
           " (relative); every other diameter and band sample is the same "
           "computation on a changed scene, with the "
           "modes up to the cutoff only";
}

}  // namespace

// Step 5.
void warn(LimitsResult& r) {
    std::vector<std::string> knife;
    for (const LimitsPoint& p : r.points) {
        const CriterionSpeed& a = p.at(Criterion::amplitude);
        if (!a.given) continue;
        for (const ResponsePeak& peak : p.peaks)
            if (std::abs(peak.web_speed_m_s - a.web_speed_m_s) <= kKnifeEdge * peak.web_speed_m_s) {
                knife.push_back(significant(p.diameter_m * 1e3, 4) + " mm (limit " +
                                formatted("%.2f", a.web_speed_m_s) + " m/s, peak " +
                                formatted("%.2f", peak.web_speed_m_s) + " m/s of " +
                                formatted("%.3f", peak.amplitude_m * 1e3) + " mm)");
                break;
            }
    }
    if (!knife.empty())
        r.warnings.push_back("knife edge: the amplitude limit is reached within " + significant(kKnifeEdge * 100, 2) +
                             " % of a resonance peak at " + join(knife, "; ") +
                             "; the limit is then the resonance itself, and a "
                             "little more bow or less damping moves it "
                             "anywhere below the peak: do not run near it (I-5's "
                             "factor keeps away from it)");
    // Criteria that disagree beyond their bands, at the case's roll: I-5 against
    // the others.
    const LimitsPoint& first = r.points.front();
    const CriterionSpeed& i5 = first.at(Criterion::i5_low);
    const auto range = [](const CriterionSpeed& c) {
        return formatted("%.2f", c.band_low_m_s) + "-" + formatted("%.2f", c.band_high_m_s) + " m/s";
    };
    std::vector<std::string> apart;
    for (Criterion c : {Criterion::koenig, Criterion::amplitude, Criterion::order1_backward}) {
        const CriterionSpeed& o = first.at(c);
        if (o.given && i5.given && (o.band_low_m_s > i5.band_high_m_s || o.band_high_m_s < i5.band_low_m_s))
            apart.push_back(std::string(criterion_name(c)) + " " + range(o));
    }
    if (!apart.empty())
        r.warnings.push_back("criteria disagree beyond their bands at " + significant(first.diameter_m * 1e3, 4) +
                             " mm: " + criterion_name(Criterion::i5_low) + " " + range(i5) + " against " +
                             join(apart, ", ") +
                             ": they answer different questions; the verdict takes "
                             "the lowest (docs/how-to/limits.md, "
                             "\"Warnings\")");
    for (size_t i = 0; i + 1 < r.points.size(); ++i) {
        const LimitsPoint &a = r.points[i], &b = r.points[i + 1];
        if (!a.order1_mode.empty() && !b.order1_mode.empty() && a.order1_mode != b.order1_mode)
            r.warnings.push_back("the mode of the first order-1 critical speed changes between " +
                                 significant(a.diameter_m * 1e3, 4) + " mm (" + a.order1_mode + ") and " +
                                 significant(b.diameter_m * 1e3, 4) + " mm (" + b.order1_mode + ")");
    }
}

std::vector<std::string> limits_notes(const LimitsResult& r) {
    std::vector<std::string> out = {(!r.points.empty() && r.points.front().equivalent_f1_hz ? std::string("f1, k, I-5 and Koenig at the coupled level, the "
                                                                         "spinning criteria and the band at the "
                                                                         "harmonic level of the axisymmetric "
                                                                         "equivalent")
                                                             : "every criterion at the " + to_string(r.level) + " level") +
                                        "; a criterion's web speed is pi Dp f_rot at that "
                                        "rest-roll diameter",
                                    "limiting: I-5 at 0.7 (Ilomaki, without a safety cage), Koenig's "
                                    "critical speed (K-1/K-2 with his experience "
                                    "factor, 0.55 for a large core), the order-1 critical speeds "
                                    "(backward and forward whirl), the order-2 one "
                                    "where an order-2 load acts (ovality with gravity), and the "
                                    "amplitude limit and, with [traction], the web's slip on its first idler "
                                    "(Rice & Gans); I-5 at 0.8 is reported",
                                    "the band: each uncertain input at each end of its range, one at a "
                                    "time, with the forced response re-solved, at every " +
                                        std::to_string(kBandStride) +
                                        "th diameter and the last; between them interpolated relative to the "
                                        "point values; "
                                        "the critical speeds of a sample are the point's scaled by the "
                                        "sample's f1 (they follow f1 within the "
                                        "gyroscopic shift, a few per cent); the safe speed's band is the "
                                        "range of the samples' own verdicts",
                                    std::string("not included: the core's strength and fatigue (durability), ") +
                                        (r.points.empty() || !r.points.front().at(Criterion::traction).given
                                             ? "the web's slip on its idlers (give [traction]: Rice & Gans), "
                                             : "") +
                                        "rotating "
                                        "(internal) damping, the contact opening at large amplitude, the "
                                        "rest paper's own out-of-roundness"};
    if (r.checks) out.push_back(checks_note(*r.checks));
    return out;
}

}  // namespace coremodal
