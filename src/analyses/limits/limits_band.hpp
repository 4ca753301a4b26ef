// The verdict's pieces at one rest-roll diameter (analyses/limits/limits.hpp):
// the criteria from one forced response and the critical speeds, and the
// band from the uncertain inputs' documented ranges (docs/how-to/limits.md, "The
// band"), each input at each end of its range, one at a time.
#pragma once

#include "analyses/fit/fit.hpp"
#include "analyses/limits/limits.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The critical web speeds of the Campbell sweep (m/s), lowest of each kind.
struct CriticalSpeeds {
    std::optional<double> order1_backward, order1_forward, order2;
};

// The criteria from a forced response at one diameter and the critical
// speeds, those scaled by `f1_ratio` (a band sample's f1 over the point's).
// The web's slip on its idler (Criterion::traction) is appended by the
// verdict: it does not depend on the roll.
std::vector<CriterionSpeed> criteria_of(const ResponseResult& response, const CriticalSpeeds& critical,
                                        double f1_ratio);

// The index of the lowest limiting criterion given, or -1.
int lowest_limiting(const std::vector<CriterionSpeed>& criteria);

// The case's response setup with the verdict's speeds at this diameter:
// kResponsePoints from kRangeBottom to kRangeTop times pi Dp f1.
ResponseSetup setup_for_range(const ResponseSetup& base, const Scene& at, double f1_estimate_hz);

// The uncertain inputs of this scene at its level, with their ranges and
// sources, and why an input does not apply.
std::vector<UncertainInput> uncertain_inputs(const Scene& scene, const ResponseSetup& base);

// The ranges a fit narrows (docs/how-to/limits.md, "Narrowing the band"): a fitted
// chuck contact stiffness (supports.*.normal_stiffness or
// expansion_pressure) replaces the contact's range by its fitted value +-
// kFitSigmas standard uncertainties, a fitted core.material.E_z the core's
// E_z range; each only where that is narrower. The scene must hold the
// fitted values (FittedCase::calibrated_text): the ranges are factors about
// them. Returns the inputs narrowed, in words for the output.
constexpr double kFitSigmas = 2.0;
std::vector<std::string> narrow_by_fit(std::vector<UncertainInput>& inputs, const FitOutcome& fit,
                                       const std::string& measurements_file);

// Every applying input at both ends: the criteria's bands and the safe
// speed's (each sample's own lowest limiting criterion) on `point`.
void propagate_band(const Scene& scene, const ResponseSetup& base, const std::vector<UncertainInput>& inputs,
                    LimitsPoint& point, int& n_solves);

// What the verdict assumed beyond the file, each with its source.
std::vector<std::string> limits_assumptions(const Scene& scene, bool case_response, const ResponseSetup& base);

// Step 5 of the verdict (limits_warnings.cpp): the warnings on r, from its
// points, and the notes of what every criterion is and what is left out.
void warn(LimitsResult& r);
std::vector<std::string> limits_notes(const LimitsResult& r);

}  // namespace coremodal
